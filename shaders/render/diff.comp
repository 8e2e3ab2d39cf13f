// Difference heat map for the viewer: |A - B| per pixel (mean over RGB of the display values),
// scaled so that u_full_scale is the hottest colour. Pixels where A and B agree show A as a dim
// grey, so that the picture keeps its context.
#include "shared/bindings.h"
#include "shared/colormap.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_DIFF_A) uniform sampler2D a_tex;  // RGBA8 display image of technique A
layout(binding = TEX_DIFF_B) uniform sampler2D b_tex;  // RGBA8 display image of technique B
layout(binding = IMG_DIFF_OUT, rgba8) uniform writeonly image2D out_heat;
layout(location = 0) uniform float u_full_scale;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(out_heat)))) return;
  vec3 a = texelFetch(a_tex, p, 0).rgb;
  vec3 b = texelFetch(b_tex, p, 0).rgb;
  float d = dot(abs(a - b), vec3(1.0 / 3.0));
  vec3 context = vec3(0.25 * dot(a, vec3(0.2126, 0.7152, 0.0722)));
  vec3 shown = d > 0.0 ? max(heat(d / max(u_full_scale, 1e-4)), context * 0.5) : context;
  imageStore(out_heat, p, vec4(shown, 1.0));
}
