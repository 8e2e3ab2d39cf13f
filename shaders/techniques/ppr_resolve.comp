// PPR resolve pass: decode each reflector pixel's offset, patch holes from the neighbours, and
// fetch the reflected colour at the source, refined by the pixel's own mirror ray. It also
// empties the other intermediate image, the next frame's projection target: no clear pass.
// With a normal-mapped or rough reflector, the thesis's approximation: keep the reflection
// distance of the mirror solution and follow the perturbed (or GGX-sampled) reflection vector
// that far, then reproject.
#include "common/gbuffer.glsl"
#include "common/ppr_mirror.glsl"
#include "shared/ppr_packing.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { PprParams params; };
layout(binding = TEX_PPR_PROJECTED) uniform usampler2D projected;  // this frame's intermediate
layout(binding = IMG_PPR_INTERMEDIATE, r32ui) uniform writeonly uimage2D next_intermediate;  // emptied here
layout(std430, binding = SSBO_PPR_REFLECTORS) readonly buffer Reflectors { PprReflector reflectors[]; };
layout(binding = TEX_LIT) uniform sampler2D lit_tex;
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;
layout(binding = IMG_OUT2, rgba16f) uniform writeonly image2D out_debug;  // offset.xy (px), hole before, hole after
layout(location = 0) uniform uint u_fraction_bits;
layout(location = 1) uniform int u_fallback;  // 1: the fallback tracer's reflection serves what projection cannot
layout(binding = TEX_PPR_FALLBACK) uniform sampler2D fallback_tex;

// What this pixel shows where projection has no answer: the fallback tracer's, or nothing.
vec4 unserved(ivec2 p) { return u_fallback == 1 ? texelFetch(fallback_tex, p, 0) : vec4(0.0); }

// The packed value at q, or PPR_EMPTY off screen.
uint packed_at(ivec2 q) {
  if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, ivec2(frame.viewport.xy)))) return PPR_EMPTY;
  return texelFetch(projected, q, 0).x;
}

#include "common/ppr_resolve.glsl"

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  imageStore(next_intermediate, p, uvec4(PPR_EMPTY));
  GSample g = gbuffer_fetch(p);
  if (!is_reflective(g) || g.reflector == 0u) {
    imageStore(out_reflection, p, is_reflective(g) ? unserved(p) : vec4(0.0));
#ifdef SSR_DEBUG_IMAGE
    imageStore(out_debug, p, vec4(0.0));
#endif
    return;
  }
  PprResolved r = ppr_resolve(p, g);
  imageStore(out_reflection, p, r.served ? r.reflection : unserved(p));
#ifdef SSR_DEBUG_IMAGE
  imageStore(out_debug, p, r.debug);
#endif
}
