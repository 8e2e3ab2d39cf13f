// The Hi-Z trace (Uludag, GPU Pro 5) over the max-depth pyramid built by hiz_pyramid.comp,
// shared by `hiz` and `stochastic`. Include after common/ssr_common.glsl.
//
// The ray is marched in pixel space with its reversed-Z depth, both affine along the projected
// segment. Where the ray stays in front of a cell's closest depth (z > max) it skips the cell and
// climbs a level; elsewhere it may pass behind something, so it descends (first advancing to
// where it reaches the cell's closest depth) until one pixel confirms the hit with the shared
// thickness test. The in-front test uses the segment's smaller depth, so rays towards the camera
// (depth growing) need no separate path. The traversal visits every cell the ray crosses, so it
// needs no jitter. A ray behind every surface of a cell by more than the thickness cannot hit
// anything there either: it skips the cell and climbs too (the pyramid's min depth), so rays
// passing behind objects do not walk them pixel by pixel.
layout(binding = TEX_HIZ) uniform sampler2D hiz_tex;  // RG32F (closest, farthest), full mip chain

// What one Hi-Z trace is allowed to do.
struct HizTrace {
  float max_distance;  // view-space ray length
  int max_iterations;  // cell visits; a ray still marching at the cap is a miss
  int start_level;     // pyramid level of the first step
  int max_level;       // coarsest level the trace climbs to
  float thickness;     // how far behind the depth buffer still counts as a hit
  bool backfaces;      // the back-face depth bounds the thickness instead
  uint own_reflector;  // the origin's planar reflector id (0: none), which it cannot hit
};

// The cell of `level` holding pixel-space point q. The last cell of a row/column also covers
// an odd source's extra texel, hence the clamp (matches the pyramid's footprints).
ivec2 hiz_cell(vec2 q, int level, ivec2 size) {
  return clamp(ivec2(floor(q / float(1 << level))), ivec2(0), size - 1);
}

// Ray parameters where the ray o + t d (inv_d = 1 / d, no zero components) crosses cell c's
// exit boundary on each axis; it leaves the cell at the smaller.
vec2 cell_exits(vec2 o, vec2 inv_d, ivec2 c, int level, ivec2 size) {
  float s = float(1 << level);
  vec2 lo = vec2(c) * s;
  vec2 hi = mix((vec2(c) + 1.0) * s, frame.viewport.xy, equal(c, size - 1));  // last cell: to the edge
  return (mix(lo, hi, greaterThan(inv_d, vec2(0.0))) - o) * inv_d;
}

// Is a ray point at reversed-Z depth `depth` more than `thickness` behind the farthest surface,
// at depth `farthest` (never behind the background)? The view distance is B / (depth + A)
// (frame.glsl), so without a division: B (farthest - depth) > thickness (depth + A)(farthest + A).
// (Two divisions per visit measured 0.01-0.03 ms of hiz's 1080p trace on the H200.)
bool behind_by(float depth, float farthest, float thickness) {
  float a = frame.proj[2][2], b = frame.proj[3][2];
  return farthest > 0.0 && b * (farthest - depth) > thickness * (depth + a) * (farthest + a);
}

TraceResult hiz_trace(vec3 origin, vec3 dir, HizTrace h) {
  bool backfaces = h.backfaces;
  // End the ray just inside the near plane: projecting a point at w <= 0 would flip it.
  float len = h.max_distance;
  float near_limit = -frame.clip.x * 1.01;
  if (dir.z > 1e-6) len = min(len, (near_limit - origin.z) / dir.z);
  vec2 uv0, uv1;
  float z0, z1;
  if (len <= 0.0 || !project_to_uv(origin, uv0, z0) || !project_to_uv(origin + dir * len, uv1, z1))
    return trace_miss(0.0);

  vec2 res = frame.viewport.xy;
  vec3 o = vec3(uv0 * res, z0);
  vec3 d = vec3(uv1 * res, z1) - o;
  // Rays along the view direction barely move on screen: clamp tiny components so the cell
  // exits stay finite (they then lie far beyond t = 1).
  vec2 dxy = vec2(abs(d.x) < 1e-6 ? 1e-6 : d.x, abs(d.y) < 1e-6 ? 1e-6 : d.y);
  vec2 inv_d = 1.0 / dxy;
  // Step this far past a cell boundary (0.01 pixel) so the next lookup lands in the next cell.
  float cross_t = 0.01 / max(abs(dxy.x), abs(dxy.y));
  // That step can be less than a float can add to q on the other axis (a ray nearly parallel
  // to one axis, leaving a cell through the other axis' boundary: at x = 632, 6e-5 pixel), so
  // q stays on the old side and the lookup finds the cell the ray has left: its exit on that
  // axis comes before t. The loop then takes the next cell on that axis (without it the ray
  // stalled until the iteration cap: most of the trace's time on corridor). Looking cells up
  // 0.01 pixel ahead instead gave a ray running just inside a row the next row's pixel (glass
  // 4K: 47.7 -> 43.9 dB).
  ivec2 step_cell = ivec2(sign(dxy));

  int top = clamp(h.max_level, 0, textureQueryLevels(hiz_tex) - 1);
  int level = clamp(h.start_level, 0, top);
  ivec2 size0 = textureSize(hiz_tex, 0);
  // Start one cell away, where the ray leaves the origin's pixel; no hit on the starting surface
  // (see the level-0 test).
  vec2 start_exits = cell_exits(o.xy, inv_d, hiz_cell(o.xy, 0, size0), 0, size0);
  float t = min(start_exits.x, start_exits.y) + cross_t;
  bool was_in_front = false;
  int i = 0;
  for (; i < h.max_iterations; ++i) {
    vec2 q = o.xy + d.xy * t;
    if (t >= 1.0 || any(lessThan(q, vec2(0.0))) || any(greaterThanEqual(q, res))) break;
    // The mip chain halves with floor; textureSize with a per-lane lod is wrong on llvmpipe.
    ivec2 size = max(size0 >> level, ivec2(1));
    ivec2 c = hiz_cell(q, level, size);
    vec2 exits = cell_exits(o.xy, inv_d, c, level, size);
    bvec2 left = lessThan(exits, vec2(t));  // the ray has left c on that axis (above)
    if (any(left)) {
      c = clamp(c + step_cell * ivec2(left), ivec2(0), size - 1);
      exits = cell_exits(o.xy, inv_d, c, level, size);
    }
    float t_exit = min(min(exits.x, exits.y), 1.0);
    vec2 bounds = texelFetch(hiz_tex, c, level).rg;
    float closest = bounds.x;
    float z_in = o.z + d.z * t, z_out = o.z + d.z * t_exit;
    if (min(z_in, z_out) > closest) {
      // In front of everything in the cell: skip it, try a coarser cell next.
      was_in_front = true;
      t = t_exit + cross_t;
      level = min(level + 1, top);
      continue;
    }
    if (z_in > closest) {
      // The ray enters in front and reaches the closest depth inside the cell (so d.z < 0):
      // nothing here can be hit before that point.
      was_in_front = true;
      t = min(t + (closest - z_in) / d.z, t_exit);
    } else if (!backfaces && behind_by(max(z_in, z_out), bounds.y, h.thickness)) {
      // Behind everything in the cell by more than the thickness (the back-face mode's
      // thickness varies per pixel: it descends instead).
      t = t_exit + cross_t;
      level = min(level + 1, top);
      continue;
    }
    if (level > 0) {
      --level;
      continue;
    }
    // One pixel: test the segment's point nearest to the surface from behind. Before the ray
    // has been seen in front, only a surface facing the ray counts: a ray that crosses a wall
    // within its origin's pixel hits it, one skimming its own surface does not.
    // (Level 0 is the depth buffer: inside_surface's test without fetching it again, and the
    // normal fetched only when it decides; the trace's time is its longest ray's chain of
    // dependent fetches.)
    float hit_depth = min(closest, max(z_in, z_out));
    vec2 uv = (vec2(c) + 0.5) * frame.viewport.zw;
    float ray_z = view_z_from_depth(hit_depth);
    bool inside = backfaces ? inside_surface(uv, ray_z, h.thickness, true)
                            : !is_background(closest) && ray_z <= view_z_from_depth(closest) &&
                                  view_z_from_depth(closest) - ray_z < h.thickness;
    if (inside && (was_in_front || dot(dir, texelFetch(g_normal_roughness, c, 0).xyz) < -0.1) &&
        hittable(c, h.own_reflector))
      return TraceResult(true, uv, float(i + 1), length(view_position(uv, hit_depth) - origin));
    // Behind by more than the thickness (or on the starting surface): go on past this pixel.
    t = t_exit + cross_t;
  }
  return trace_miss(float(i));
}

