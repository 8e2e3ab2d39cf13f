// Display: turns the chosen view into an 8-bit sRGB image (PNG, window) and a linear float
// image (EXR, metrics). Tone mapping happens only here.
#include "common/gbuffer.glsl"
#include "common/environment.glsl"
#include "shared/tonemap.h"
#include "shared/display.h"
#include "shared/classification.h"
#include "shared/telemetry.h"
#include "shared/colormap.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = TEX_REFLECTION) uniform sampler2D reflection_tex;
layout(binding = TEX_COLOR) uniform sampler2D color_tex;
layout(binding = IMG_OUT, rgba8) uniform writeonly image2D out_display;
layout(binding = IMG_OUT2, rgba16f) uniform writeonly image2D out_linear;
layout(location = 0) uniform int u_view;
layout(binding = TEX_DEBUG) uniform sampler2D debug_tex;
layout(binding = TEX_GLASS_SURFACE) uniform sampler2D glass_surface_tex;
layout(binding = TEX_REFRACTION) uniform sampler2D refraction_tex;
layout(binding = TEX_MOTION) uniform sampler2D motion_tex;
layout(binding = TEX_STAGE_VIEW) uniform sampler2D stage_tex;  // a stage view's texture (any size)
// The telemetry views' per-pixel words (render/telemetry.h; bound only for those views).
layout(std430, binding = SSBO_TELEMETRY) readonly buffer TelemetryBlock {
  TelemetryHeader telemetry;
  uint telemetry_hist[TELEMETRY_BINS];
  uint telemetry_pixels[];
};

#include "common/display_views.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  bool hdr;
  vec3 v = display_view(p, hdr);
  vec3 shown = hdr ? display_transform(v, frame.settings.y) : clamp(v, 0.0, 1.0);
  imageStore(out_display, p, vec4(shown, 1.0));
  imageStore(out_linear, p, vec4(v, 1.0));
}
