// PPR's resolve (include-only): what one reflector pixel shows. The source position its packed
// offset names (holes patched from the neighbours whose sources mirror back next to it), the lit
// colour there, and with a normal-mapped or rough reflector the thesis's approximation: keep the
// mirror solution's reflection distance, follow the perturbed (or GGX-sampled) reflection
// vector that far, then reproject.
//
// The pass provides (techniques/ppr_resolve.comp): `params` (PprParams), `u_fraction_bits`,
// `packed_at(q)` (the packed value at q, PPR_EMPTY off screen), `reflectors[]`, `lit_tex`.
#include "shared/sampling.h"

// With a fallback tracer, where the thesis's approximation for rough reflectors is replaced
// (measured on ramp's bands and corridor's glossy floor; see ppr_resolve()):
const float PPR_FALLBACK_ROUGHNESS = 0.35;  // from this roughness the fallback answers, hit or miss
const float PPR_OFF_SURFACE = 0.02;         // an approximated point this far off the depth buffer
                                            // (a share of its depth) is off the surface

struct PprResolved {
  bool served;      // false: projection has no answer here (the pass asks its fallback)
  vec4 reflection;  // rgb radiance, a confidence
  vec4 debug;       // offset to the source (px); z: a hole before patching; w: no projected answer
                    // (a hole left, or a source refused for the fallback): the holes view's r, g
};

// The source position (continuous pixel coordinates) that the packed value w at pixel q names.
vec2 ppr_source_at(ivec2 q, uint w) { return vec2(q) + 0.5 + ppr_unpack(w, u_fraction_bits); }

// Borrows a neighbour's source as it is. Moving it by the destination's step assumed the mirror
// keeps screen orientation and went the wrong way along the flipped axis. A borrowed source must
// also mirror back next to this pixel: otherwise this pixel's true reflection is something else
// (often the sky past an object's outline), and it stays a hole.
bool ppr_patch_hole(ivec2 p, PprReflector r, inout vec2 source) {
  const ivec2 dirs[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
                                 ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));
  int n = params.hole_fill == 1 ? 4 : 8;
  for (int i = 0; i < n; ++i) {
    uint w = packed_at(p + dirs[i]);
    if (ppr_is_empty(w)) continue;
    vec2 borrowed = ppr_source_at(p + dirs[i], w);
    ivec2 b = clamp(ivec2(borrowed), ivec2(0), ivec2(frame.viewport.xy) - 1);
    vec2 back;
    if (!mirror_to_pixel(view_position(borrowed * frame.viewport.zw, texelFetch(g_depth, b, 0).r), r, back)) continue;
    if (distance(back, vec2(p) + 0.5) > 1.5) continue;
    source = borrowed;
    return true;
  }
  return false;
}

// The projected source is first order: a magnified source was splatted over its footprint
// with the Jacobian of its own tangent plane, up to 2 px away and also past the source's
// outline. This pixel's own mirror ray (origin, dir), intersected with the tangent plane of the
// surface at the source, lands where the ray really meets it; three steps, so a curved source
// converges. The answer must be consistent: the ray meets the tangent plane of pixel s inside
// pixel s, within two pixel widths of the point the G-buffer holds there (seen edge on, at an
// outline, the whole plane projects into the pixel). Otherwise the ray passes the surface.
// Two widths, not one: one rejected more of corridor's and pedestal's good sources (floors
// against the ideal, 640x360: 33.51 / 26.16 / 33.60 dB for gallery / corridor / pedestal with
// one width, 33.56 / 26.13 / 34.12 with two). `hit_t`: the ray parameter of the last plane met.
const int PPR_REFINED = 0, PPR_INTO_BACKGROUND = 1, PPR_INCONSISTENT = 2;

// Where the ray origin + t dir meets the tangent plane of the surface the G-buffer holds at
// pixel s (x: that surface point); where the ray grazes the plane, t is the ray's distance to
// x's foot. False on the background.
bool ppr_tangent_plane(ivec2 s, vec3 origin, vec3 dir, out vec3 x, out float t, out bool grazing) {
  float depth = texelFetch(g_depth, s, 0).r;
  if (is_background(depth)) return false;
  x = view_position(pixel_to_uv(s), depth);
  vec3 n = texelFetch(g_normal_roughness, s, 0).xyz;
  float denom = dot(dir, n);
  grazing = abs(denom) < 1e-3 * length(n);
  t = grazing ? dot(x - origin, dir) : dot(x - origin, n) / denom;
  return true;
}

int ppr_refine(inout vec2 source, vec3 origin, vec3 dir, out float hit_t) {
  hit_t = 0.0;
  for (int i = 0; i < 3; ++i) {
    ivec2 s = clamp(ivec2(source), ivec2(0), ivec2(frame.viewport.xy) - 1);
    vec3 x;
    float t;
    bool grazing;
    if (!ppr_tangent_plane(s, origin, dir, x, t, grazing)) return PPR_INTO_BACKGROUND;
    hit_t = t;
    if (grazing) return PPR_REFINED;  // keep the projected source
    vec2 uv;
    float d;
    if (!(t > 0.0) || !project_to_uv(origin + dir * t, uv, d)) return PPR_INCONSISTENT;
    vec2 moved = uv * frame.viewport.xy;
    if (all(lessThan(abs(moved - (vec2(s) + 0.5)), vec2(0.5 + 1e-3)))) {
      source = moved;
      float pixel_size = 2.0 * abs(x.z) / (frame.proj[1][1] * frame.viewport.y);
      return distance(origin + dir * t, x) <= 2.0 * pixel_size ? PPR_REFINED : PPR_INCONSISTENT;
    }
    source = moved;
  }
  return PPR_INCONSISTENT;
}

// Whether this pixel's ray meets another surface before its refined source, at the source a
// neighbour took. The projection keeps one source per pixel, the closest mirror image that landed
// there, which need not be the surface the ray meets first: where a near object's mirror image
// is magnified past its splat (its outline seen edge on from the camera, gallery's spheres) or
// its splats leave a pinhole, the surface behind it fills the pixel, and the refinement holds
// there too, since that surface is where the ray would go on. Evidence of the nearer surface: a
// neighbour's source elsewhere (over 2 px from this one) whose tangent plane the ray crosses
// first, within a pixel of that source. Gallery's floor against the ideal (llvmpipe), before ->
// after: 33.63 -> 35.65 dB at 1920x1080 (hiz 34.53), 33.56 -> 34.93 at 640x360; a reach of 3 px
// handed more good pixels to the fallback (35.95 at 1080p but 33.85 at 640x360, the cylinder's
// crop -0.8 dB), and choosing the neighbour's source instead of the fallback failed: the nearer
// surface is seen edge on there and the refinement does not converge on it.
bool ppr_nearer_surface_beside(ivec2 p, vec2 source, vec3 origin, vec3 dir, float hit_t) {
  // ppr_patch_hole's neighbours; one array at file scope measured 0.01 ms slower (H200, 1080p).
  const ivec2 dirs[8] = ivec2[8](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1),
                                 ivec2(1, 1), ivec2(-1, 1), ivec2(1, -1), ivec2(-1, -1));
  for (int i = 0; i < 8; ++i) {
    uint w = packed_at(p + dirs[i]);
    if (ppr_is_empty(w)) continue;
    vec2 other = ppr_source_at(p + dirs[i], w);
    if (distance(other, source) < 2.0) continue;  // the same stretch of surface
    ivec2 s = clamp(ivec2(other), ivec2(0), ivec2(frame.viewport.xy) - 1);
    vec3 x;
    float t;
    bool grazing;
    if (!ppr_tangent_plane(s, origin, dir, x, t, grazing)) continue;
    vec2 uv;
    float d;
    if (t > 0.0 && t < 0.98 * hit_t && project_to_uv(origin + dir * t, uv, d) &&
        distance(uv * frame.viewport.xy, vec2(s) + 0.5) <= 1.0)
      return true;
  }
  return false;
}

// The perturbed rays' mean radiance at the mirror solution's reach; false when every one left
// the screen (the ray left the plane's solution). `off_surface`: a ray's point at that reach
// lies off the depth buffer's surface there (PPR_OFF_SURFACE), so the ray itself goes elsewhere.
bool ppr_perturbed(ivec2 p, GSample g, vec2 source, float rough, inout vec3 color, out bool off_surface) {
  vec2 src_uv = source * frame.viewport.zw;
  vec3 hit_vs = view_position(src_uv, texelFetch(g_depth, ivec2(source), 0).r);
  float reach = length(hit_vs - g.pos_vs);
  vec3 v_dir = -normalize(g.pos_vs);
  int n = rough < SSR_MIRROR_ROUGHNESS ? 1 : clamp(params.samples, 1, 16);
  vec3 sum = vec3(0.0);
  float found = 0.0;
  off_surface = false;
  for (int s = 0; s < n; ++s) {
    vec3 dir = reflect(-v_dir, g.n_vs);  // the G-buffer normal carries the normal map
    if (rough >= SSR_MIRROR_ROUGHNESS) {
      vec3 l = sample_reflection(g.n_vs, v_dir, rough, sample_xi(uint(p.x), uint(p.y), uint(s), uint(params.seed)));
      if (dot(l, g.n_vs) > 0.0) dir = l;
    }
    vec2 uv;
    float depth;
    vec3 at = g.pos_vs + dir * reach;
    if (project_to_uv(at, uv, depth) && uv_on_screen(uv)) {
      sum += textureLod(lit_tex, uv, 0.0).rgb;
      found += 1.0;
      off_surface = off_surface || abs(scene_view_z(uv) - at.z) > PPR_OFF_SURFACE * abs(at.z);
    }
  }
  if (found > 0.0) color = sum / found;
  return found > 0.0;
}

PprResolved ppr_resolve(ivec2 p, GSample g) {
  // The source position (continuous pixel coordinates) this pixel reflects.
  uint v = packed_at(p);
  bool hole = ppr_is_empty(v);
  vec2 source = hole ? vec2(p) + 0.5 : ppr_source_at(p, v);
  if (hole && params.hole_fill > 0) hole = !ppr_patch_hole(p, reflectors[g.reflector - 1u], source);
  if (hole) return PprResolved(false, vec4(0.0), vec4(0.0, 0.0, 1.0, 1.0));
  // The plane's own normal (a normal map tilts the G-buffer's) gives the mirror ray.
  vec3 plane_n = normalize(mat3(frame.view) * reflectors[g.reflector - 1u].plane.xyz);
  vec3 mirror_dir = reflect(normalize(g.pos_vs), plane_n);
  vec2 refined = source;
  float hit_t;
  int refine = ppr_refine(refined, g.pos_vs, mirror_dir, hit_t);
  // With a fallback tracer: a ray that leaves the source's outline into the background has no
  // projected answer; a patched hole keeps its borrowed source only where the refinement holds
  // and the fallback found a hit too (at an outline the borrowed ray may pass into the sky by a
  // fraction of a pixel); another inconsistent source, or a refined one with a nearer surface
  // beside it, goes to the fallback where that found a hit. Elsewhere (and without a fallback:
  // the thesis's technique) the projection stands: always falling back cost corridor's floor
  // 1.5 dB, where hiz misses more than projection.
  bool patched = ppr_is_empty(v);
  bool fallback_hit = u_fallback == 1 && texelFetch(fallback_tex, p, 0).a > 0.5;
  if (refine == PPR_REFINED && patched && u_fallback == 1 && !fallback_hit)
    refine = PPR_INTO_BACKGROUND;
  if (refine == PPR_REFINED && fallback_hit && ppr_nearer_surface_beside(p, source, g.pos_vs, mirror_dir, hit_t))
    refine = PPR_INCONSISTENT;
  if (refine == PPR_REFINED)
    source = refined;
  else if (u_fallback == 1 && (refine == PPR_INTO_BACKGROUND || patched || fallback_hit))
    return PprResolved(false, vec4(0.0), vec4(0.0, 0.0, patched ? 1.0 : 0.0, 1.0));
  vec4 debug = vec4(source - (vec2(p) + 0.5), patched ? 1.0 : 0.0, 0.0);
  float rough = params.roughness >= 0.0 ? params.roughness : g.roughness;
  bool bumpy = params.normal_maps != 0 && abs(dot(g.n_vs, plane_n)) < 0.99999;
  // A normal-mapped mirror's rays leave the plane's solution: its reach is a guess that put
  // ripples 8 dB under hiz (640x360). The fallback traces them; without one, the guess stands.
  if (bumpy && rough < SSR_MIRROR_ROUGHNESS && u_fallback == 1) return PprResolved(false, vec4(0.0), debug);
  // Rough reflectors spread their rays too far from the mirror solution for its reach to say
  // where they go: the fallback answers them, hit or miss (ramp's bands, 1080p, llvmpipe: the
  // approximation ahead of hiz up to roughness 0.3, behind from 0.4 by 0.1 to 1.2 dB).
  if (rough >= PPR_FALLBACK_ROUGHNESS && u_fallback == 1) return PprResolved(false, vec4(0.0), debug);
  // Nearest, as the ideal reads: a bilinear fetch at an exact source blurs across outlines.
  vec3 color = texelFetch(lit_tex, ivec2(source), 0).rgb;
  bool off_surface = false;
  if ((bumpy || rough >= SSR_MIRROR_ROUGHNESS) && !ppr_perturbed(p, g, source, rough, color, off_surface) && u_fallback == 1)
    return PprResolved(false, vec4(0.0), debug);
  // The approximation's point off every surface: the sampled ray goes elsewhere. Where the
  // fallback hit, take its answer: it traced the same first sample (same sequence and seed).
  // (Corridor's glossy floor, whose far end reflects the ceiling lights: 26.77 -> 27.55 dB at
  // 4K, llvmpipe, hiz 27.27; taking the fallback on every glossy pixel: pedestal's floor -0.2.)
  if (off_surface && fallback_hit) return PprResolved(false, vec4(0.0), debug);
  float a = 1.0;
  if (params.edge_fade != 0) a *= edge_fade(source * frame.viewport.zw);
  return PprResolved(true, vec4(color, a), debug);
}
