// The `dda` trace (include-only); the pass (techniques/dda.comp) provides
// `params` (DdaParams) and includes common/ssr_common.glsl first.

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

// Where the stretch [lo, hi] of the ray lies relative to the surface seen at its middle's pixel.
// The paper's z-range test: the stretch's view-z interval, not one point, is compared with the
// depth buffer, so a ray crossing a lot of depth inside one pixel (a reflection heading away
// from the camera: metres per pixel) cannot jump over a thin slab. The interval overlaps the
// slab exactly when its point nearest the front surface from behind, min(z_near, front), is
// inside_surface() -- which keeps the shared back-face thickness option working.
int classify(ScreenRay r, float lo, float hi, bool backfaces, out vec2 uv) {
  uv = (vec2(ray_pixel(r, 0.5 * (lo + hi))) + 0.5) * frame.viewport.zw;
  float front = scene_view_z(uv);  // -1e30 on the background: always FRONT there
  float za = ray_z(r, lo), zb = ray_z(r, hi);
  if (min(za, zb) > front) return FRONT;
  return inside_surface(uv, min(max(za, zb), front), params.thickness, backfaces) ? INSIDE : BEHIND;
}

// Is the surface seen at uv the origin's own surface, continued along its tangent plane? Near
// the origin, per-pixel depth quantisation makes a ray leaving a surface look "inside" that
// surface's neighbouring pixels; a surface in front of the tangent plane (a wall rising from a
// floor) is another surface, hittable at once. Beyond the tangent plane (convex) counts as own.
bool origin_surface(vec2 uv, vec3 origin, vec3 n) {
  vec3 d = view_position(uv, 1.0);  // a point on the pixel's view ray (reversed-Z: the near plane)
  float nd = dot(n, d);
  if (nd >= -1e-6) return false;    // the plane is not seen through this pixel
  float plane_z = dot(n, origin) / nd * d.z;
  return scene_view_z(uv) <= plane_z + 1e-3 * abs(plane_z);
}

bool on_screen(ivec2 px) { return all(greaterThanEqual(px, ivec2(0))) && all(lessThan(px, ivec2(frame.viewport.xy))); }

TraceResult dda_trace(ivec2 pixel, vec3 origin, vec3 dir, float jitter) {
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
  // A ray along the view ray projects to (almost) a point: nudge its end by 0.01 px per axis
  // as the paper does, so nothing divides by zero. It then ends inside the origin's pixel,
  // before the first step: a miss.
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
  // Each step covers a stretch [lo, hi] of the ray and tests the pixel at its middle: stretches
  // tile the ray from where it leaves the origin's pixel (s = 0.5), so no crossing falls between
  // two steps. Jitter shortens the first stretch to (1 - jitter) * stride, shifting the grid of
  // all later ones per pixel (banding becomes noise) without skipping the ray's start, where the
  // paper's offset start would lose contact reflections.
  float lo = 0.5;
  float hi = lo + stride * (params.jitter != 0 ? 1.0 - jitter : 1.0);
  float steps = 0.0;
  // A hit needs the ray to have been wholly in front of the visible surface at an earlier step,
  // or a surface that is not the origin's own (see origin_surface). A ray that does not start
  // on the depth buffer's surface (refraction: on glass in front of it) cannot hit itself.
  float own_z = scene_view_z(pixel_to_uv(pixel));
  bool armed = origin.z > own_z + 1e-4 * abs(own_z);
  vec3 n = texelFetch(g_normal_roughness, pixel, 0).xyz;
  n = dot(n, n) > 1e-8 ? normalize(n) : vec3(0.0, 0.0, 1.0);
  uint own = origin_reflector(pixel, origin);
  int prev = FRONT;  // the ray starts on the surface
  for (int i = 0; i < params.max_steps && lo < r.len; ++i, lo = hi, hi += stride) {
    hi = min(hi, r.len);
    if (!on_screen(ray_pixel(r, 0.5 * (lo + hi)))) return trace_miss(steps);
    steps += 1.0;
    vec2 uv;
    int c = classify(r, lo, hi, backfaces, uv);
    // A stride-wide stretch is judged by its middle pixel only: a ray that went from in front to
    // behind it may have entered a slab at another pixel of the stretch, so look there too.
    if (c == INSIDE || (c == BEHIND && prev == FRONT)) {
      // Bisect the stretch for where the ray point first reaches the surface, then test the last
      // sub-stretch (<= 1 px with enough steps). Without refinement the stretch's answer stands,
      // as in the paper.
      float a = lo, b = hi;
      int f = c;
      for (int k = 0; k < params.refine_steps && b - a > 1.0; ++k) {
        float m = 0.5 * (a + b);
        vec2 muv;
        steps += 1.0;
        if (classify(r, m, m, backfaces, muv) != FRONT) b = m; else a = m;
      }
      if (b - a < hi - lo) {
        steps += 1.0;
        f = classify(r, a, b, backfaces, uv);
      }
      if (f == INSIDE && (armed || !origin_surface(uv, origin, n)) && hittable(ivec2(uv * frame.viewport.xy), own))
        return TraceResult(true, uv, steps, length(ray_view(r, 0.5 * (a + b)) - origin));
    }
    armed = armed || c == FRONT;
    prev = c;
  }
  return trace_miss(steps);
}
