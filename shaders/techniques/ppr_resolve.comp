// PPR resolve pass: decode each reflector pixel's offset, patch holes from the neighbours, and
// fetch the reflected colour at the (sub-pixel) source position. It also empties the other
// intermediate image, the next frame's projection target: no clear pass. With a normal-mapped or rough
// reflector, the thesis's approximation: keep the reflection distance of the mirror solution
// and follow the perturbed (or GGX-sampled) reflection vector that far, then reproject.
#include "common/gbuffer.glsl"
#include "common/ppr_mirror.glsl"
#include "shared/ppr_packing.h"
#include "shared/sampling.h"

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

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) return;
  imageStore(next_intermediate, p, uvec4(PPR_EMPTY));
  GSample g = gbuffer_fetch(p);
  if (!is_reflective(g) || g.reflector == 0u) {
    imageStore(out_reflection, p, is_reflective(g) ? unserved(p) : vec4(0.0));
    imageStore(out_debug, p, vec4(0.0));
    return;
  }
  // The source position (continuous pixel coordinates) this pixel reflects.
  uint v = packed_at(p);
  bool hole = ppr_is_empty(v);
  vec2 source = vec2(p) + 0.5 + (hole ? vec2(0.0) : ppr_unpack(v, u_fraction_bits));
  if (hole && params.hole_fill > 0) {
    // Borrow a neighbour's source as it is. Moving it by the destination's step assumed the
    // mirror keeps screen orientation and went the wrong way along the flipped axis. A borrowed
    // source must also mirror back next to this pixel: otherwise this pixel's true reflection
    // is something else (often the sky past an object's outline), and it stays a hole.
    const ivec2 dirs[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
                                   ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));
    PprReflector r = reflectors[g.reflector - 1u];
    int n = params.hole_fill == 1 ? 4 : 8;
    for (int i = 0; i < n && hole; ++i) {
      uint w = packed_at(p + dirs[i]);
      if (ppr_is_empty(w)) continue;
      vec2 borrowed = vec2(p + dirs[i]) + 0.5 + ppr_unpack(w, u_fraction_bits);
      ivec2 b = clamp(ivec2(borrowed), ivec2(0), ivec2(frame.viewport.xy) - 1);
      vec2 back;
      if (!mirror_to_pixel(view_position(borrowed * frame.viewport.zw, texelFetch(g_depth, b, 0).r), r, back)) continue;
      if (distance(back, vec2(p) + 0.5) > 1.5) continue;
      source = borrowed;
      hole = false;
    }
  }
  if (hole) {
    imageStore(out_reflection, p, unserved(p));
    imageStore(out_debug, p, vec4(0.0, 0.0, 1.0, 1.0));
    return;
  }
  vec2 src_uv = source * frame.viewport.zw;
  vec3 color = textureLod(lit_tex, src_uv, 0.0).rgb;

  float rough = params.roughness >= 0.0 ? params.roughness : g.roughness;
  // A normal map tilts the G-buffer normal away from the reflector's plane.
  vec3 plane_n = normalize(mat3(frame.view) * reflectors[g.reflector - 1u].plane.xyz);
  bool bumpy = params.normal_maps != 0 && abs(dot(g.n_vs, plane_n)) < 0.99999;
  bool perturbed = bumpy || rough >= 0.01;
  if (perturbed) {
    // Mirror solution: the reflected point and its distance from this pixel's surface point.
    vec3 hit_vs = view_position(src_uv, texelFetch(g_depth, ivec2(source), 0).r);
    float reach = length(hit_vs - g.pos_vs);
    vec3 v_dir = -normalize(g.pos_vs);
    int n = rough < 0.01 ? 1 : clamp(params.samples, 1, 16);
    vec3 sum = vec3(0.0);
    float found = 0.0;
    for (int s = 0; s < n; ++s) {
      vec3 dir = reflect(-v_dir, g.n_vs);  // the G-buffer normal carries the normal map
      if (rough >= 0.01) {
        vec3 l = sample_reflection(g.n_vs, v_dir, rough, sample_xi(uint(p.x), uint(p.y), uint(s), uint(params.seed)));
        if (dot(l, g.n_vs) > 0.0) dir = l;
      }
      vec2 uv;
      float depth;
      if (project_to_uv(g.pos_vs + dir * reach, uv, depth) && uv_on_screen(uv)) {
        sum += textureLod(lit_tex, uv, 0.0).rgb;
        found += 1.0;
      }
    }
    if (found > 0.0) color = sum / found;
    else if (u_fallback == 1) {  // the perturbed ray left the plane's solution
      imageStore(out_reflection, p, unserved(p));
      imageStore(out_debug, p, vec4(source - (vec2(p) + 0.5), ppr_is_empty(v) ? 1.0 : 0.0, 0.0));
      return;
    }
  }
  float a = 1.0;
  if (params.edge_fade != 0) a *= clamp(1.0 - abs(src_uv.x - 0.5) - abs(src_uv.y - 0.5), 0.0, 1.0);
  imageStore(out_reflection, p, vec4(color, a));
  imageStore(out_debug, p, vec4(source - (vec2(p) + 0.5), ppr_is_empty(v) ? 1.0 : 0.0, 0.0));
}
