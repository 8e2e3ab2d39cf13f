// `none`: confidence 0 everywhere (written by a pass as cheap as any, so timings compare fairly).
#include "shared/bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;

void main() { imageStore(out_reflection, ivec2(gl_GlobalInvocationID.xy), vec4(0.0)); }
