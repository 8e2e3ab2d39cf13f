// `dda` (McGuire & Mara 2014): perspective-correct per-pixel screen-space march
// (see src/techniques/dda.cpp).
#include "common/ssr_common.glsl"
#include "shared/dda.h"

layout(std140, binding = UBO_TECHNIQUE) uniform ParamsBlock { DdaParams params; };

// The clipped ray in screen space, parametrised by s = pixels along its major axis (0 at the
// origin, len at the end). P (pixels), Q = view/w and k = 1/w are all linear in s, so the view
// position at s is Q/k: perspective-correct without a per-step projection. Stepping by
// dp = delta / max(|delta.x|, |delta.y|) moves exactly one pixel along the major axis: the
// paper's x/y permutation, without swapping coordinates back for every fetch.
struct ScreenRay {
  vec2 p0, dp;
  vec3 q0, dq;
  float k0, dk;
  float len;
};

vec3 ray_view(ScreenRay r, float s) { return (r.q0 + r.dq * s) / (r.k0 + r.dk * s); }
float ray_z(ScreenRay r, float s) { return (r.q0.z + r.dq.z * s) / (r.k0 + r.dk * s); }
ivec2 ray_pixel(ScreenRay r, float s) { return ivec2(floor(r.p0 + r.dp * s)); }

const int FRONT = 0, INSIDE = 1, BEHIND = 2;

// Where the stretch [s - half, s + half] of the ray lies relative to the surface seen at s's
// pixel. The paper's z-range test: the stretch's view-z interval, not one point, is compared
// with the depth buffer, so a ray crossing a lot of depth inside one pixel (or one stride)
// cannot jump over a thin surface. The interval overlaps the surface's slab exactly when its
// point nearest to the front surface from behind, min(z_near, front), is inside_surface() --
// which keeps the shared back-face thickness option working.
int classify(ScreenRay r, float s, float half_len, bool backfaces, out vec2 uv) {
  uv = (vec2(ray_pixel(r, s)) + 0.5) * frame.viewport.zw;
  float front = scene_view_z(uv);  // -1e30 on the background: always FRONT there
  float za = ray_z(r, max(s - half_len, 0.0)), zb = ray_z(r, min(s + half_len, r.len));
  if (min(za, zb) > front) return FRONT;
  return inside_surface(uv, min(max(za, zb), front), params.thickness, backfaces) ? INSIDE : BEHIND;
}

bool on_screen(ivec2 px) { return all(greaterThanEqual(px, ivec2(0))) && all(lessThan(px, ivec2(frame.viewport.xy))); }

TraceResult trace_ray(ivec2 pixel, vec3 origin, vec3 dir, float jitter) {
  // Clip against the near plane before projecting: a ray towards the camera ends on it, so
  // both endpoints have w = -z >= near > 0 and nothing divides by w <= 0.
  float near_z = -frame.clip.x;
  float length_vs = params.max_distance;
  if (origin.z + dir.z * length_vs > near_z) length_vs = max((near_z - origin.z) / dir.z, 0.0);
  vec3 end = origin + dir * length_vs;

  vec4 h0 = frame.proj * vec4(origin, 1.0), h1 = frame.proj * vec4(end, 1.0);
  float k0 = 1.0 / h0.w, k1 = 1.0 / h1.w;
  vec2 p0 = (h0.xy * k0 * 0.5 + 0.5) * frame.viewport.xy;
  vec2 p1 = (h1.xy * k1 * 0.5 + 0.5) * frame.viewport.xy;
  // A ray along the view ray projects to (almost) a point: lengthen it to 0.1 px as the paper
  // does, so the step never divides by zero. It then ends before its first step: a miss.
  vec2 delta = p1 - p0;
  if (dot(delta, delta) < 1e-4) delta += vec2(0.01);
  float major = max(max(abs(delta.x), abs(delta.y)), 1e-4);

  ScreenRay r;
  r.p0 = p0;
  r.dp = delta / major;
  r.q0 = origin * k0;
  r.dq = (end * k1 - r.q0) / major;
  r.k0 = k0;
  r.dk = (k1 - k0) / major;
  r.len = major;

  bool backfaces = params.ray.backface_thickness != 0;
  float stride = max(params.stride, 1.0);
  // The first step leaves the origin's pixel; jitter shifts all steps by up to one stride so
  // neighbouring pixels sample different depths (banding becomes noise).
  float first = 1.0 + (params.jitter != 0 ? jitter * stride : 0.0);
  float s_prev = 0.0, steps = 0.0;
  // A hit needs the ray to have been wholly in front of the visible surface at an earlier step:
  // near its origin the ray can look "inside" its own surface (per-pixel depth quantisation).
  bool armed = false;
  for (int i = 0; i < params.max_steps; ++i) {
    float s = min(first + stride * float(i), r.len);  // the last step lands on the ray's end
    if (s <= s_prev) break;
    if (!on_screen(ray_pixel(r, s))) return trace_miss(steps);
    steps += 1.0;
    vec2 uv;
    int c = classify(r, s, 0.5 * stride, backfaces, uv);
    if (armed && c == INSIDE) {
      if (stride <= 1.0 || params.refine_steps <= 0) return TraceResult(true, uv, steps, length(ray_view(r, s) - origin));
      // Bisect (s_prev, s] for the first pixel the ray reaches the surface at (not FRONT; s_prev
      // was not a hit), testing one pixel's z-range at a time; stop at pixel precision.
      float a = s_prev, b = s;
      for (int k = 0; k < params.refine_steps && b - a > 1.0; ++k) {
        float m = 0.5 * (a + b);
        vec2 muv;
        steps += 1.0;
        if (classify(r, m, 0.5, backfaces, muv) != FRONT) b = m; else a = m;
      }
      // Confirm at pixel scale: a stride-wide z-range can overlap a slab the ray never enters.
      steps += 1.0;
      if (classify(r, b, 0.5, backfaces, uv) == INSIDE) return TraceResult(true, uv, steps, length(ray_view(r, b) - origin));
    }
    armed = armed || c == FRONT;
    s_prev = s;
  }
  return trace_miss(steps);
}

#include "common/ssr_main.glsl"
