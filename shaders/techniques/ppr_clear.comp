// PPR: empties an intermediate image, on the first frame and after a reset only: afterwards each
// frame's resolve empties the next frame's (a compute pass: glClearTexImage measured 5x slower
// on the NVIDIA driver for this r32ui image).
#include "shared/ppr.h"
#include "shared/ppr_packing.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = IMG_PPR_INTERMEDIATE, r32ui) uniform writeonly uimage2D intermediate;

void main() { imageStore(intermediate, ivec2(gl_GlobalInvocationID.xy), uvec4(PPR_EMPTY)); }
