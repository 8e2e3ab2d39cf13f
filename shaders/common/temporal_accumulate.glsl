// Denoiser stage 2's algorithm (include-only): see denoise/temporal.comp for what it does. The
// pass provides `pass` (DenoisePass), current_tex, history_tex, history_stats, motion_tex,
// prev_depth_tex and prev_normal_tex.

// Last frame's uv of a world point; false behind last frame's camera.
bool previous_uv(vec3 world, out vec2 uv, out float depth) {
  return clip_to_uv(frame.prev_view_proj * vec4(world, 1.0), uv, depth);
}

// Was the surface seen at last frame's `uv` like this pixel's (normal and roughness; with
// `expected_depth` >= 0 also at the depth this pixel's point had there)?
bool same_surface(vec2 uv, GSample g, float expected_depth) {
  if (!uv_on_screen(uv)) return false;
  ivec2 q = ivec2(uv * frame.viewport.xy);
  float prev_depth = texelFetch(prev_depth_tex, q, 0).r;
  if (is_background(prev_depth)) return false;
  vec4 nr = texelFetch(prev_normal_tex, q, 0);
  if (abs(nr.w - g.roughness) > 0.1) return false;
  // Last frame's normals are in last frame's view space.
  vec3 n_prev_view = mat3(frame.prev_view) * view_to_world_dir(g.n_vs);
  if (dot(nr.xyz, n_prev_view) < 0.9) return false;
  if (expected_depth < 0.0) return true;
  float z_prev = view_z_from_depth(prev_depth), z_exp = view_z_from_depth(expected_depth);
  return abs(z_prev - z_exp) <= 0.03 * abs(z_exp);
}

// Last frame's history at `uv`, bilinear over the texels that held one (frames >= 1). A texel
// that did not (not reflective last frame) is stored as zeros: averaged in, it pulled the
// radiance, its confidence and the frame count towards 0 along every edge that moved (corridor's
// disoccluded floor next to its pillars). False when none of the four held one.
bool history_at(vec2 uv, out vec4 radiance, out vec2 stats) {
  vec2 st = uv * frame.viewport.xy - 0.5;
  ivec2 base = ivec2(floor(st));
  vec2 f = st - vec2(base);
  // Gathered at the four texels' shared corner, so it reads exactly the block the weights are
  // for (at uv itself, the hardware's sub-texel rounding may pick the next block near a centre).
  vec4 frames = textureGather(history_stats, (vec2(base) + 1.0) * frame.viewport.zw, 1);  // (0,1) (1,1) (1,0) (0,0)
  bvec4 held = greaterThanEqual(frames, vec4(1.0));
  if (all(held)) {  // inside a surface: the sampler's bilinear fetch
    radiance = textureLod(history_tex, uv, 0.0);
    stats = textureLod(history_stats, uv, 0.0).rg;
    return true;
  }
  radiance = vec4(0.0);
  stats = vec2(0.0);
  vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y)) * vec4(held);
  float total = w.x + w.y + w.z + w.w;
  if (!(total > 0.0)) return false;
  const ivec2 corner[4] = ivec2[](ivec2(0, 1), ivec2(1, 1), ivec2(1, 0), ivec2(0, 0));
  for (int k = 0; k < 4; ++k) {
    if (!(w[k] > 0.0)) continue;
    ivec2 q = clamp(base + corner[k], ivec2(0), ivec2(frame.viewport.xy) - 1);  // as clamp-to-edge
    radiance += w[k] * texelFetch(history_tex, q, 0);
    stats += w[k] * texelFetch(history_stats, q, 0).rg;
  }
  radiance /= total;
  stats /= total;
  return true;
}

// The mean and spread of the current image's 3x3 texels around texel c (clamped at its edges).
void temporal_neighbourhood(ivec2 c, out vec4 mean, out vec4 sigma) {
  vec4 m1 = vec4(0.0), m2 = vec4(0.0);
  ivec2 last = textureSize(current_tex, 0) - 1;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) {
      vec4 s = texelFetch(current_tex, clamp(c + ivec2(x, y), ivec2(0), last), 0);
      m1 += s;
      m2 += s * s;
    }
  mean = m1 / 9.0;
  sigma = sqrt(max(m2 / 9.0 - mean * mean, vec4(0.0)));
}

// This pixel's accumulated radiance (premultiplied) and its (variance, frames accumulated), from
// its current value and stats and its neighbourhood's mean and spread (temporal_neighbourhood).
void temporal_accumulate(ivec2 p, GSample g, vec4 current, vec2 stats, vec4 mean, vec4 sigma, out vec4 result,
                         out vec2 out_stats_value) {
  bool valid = frame.time.z > 0.5;
  vec3 world = view_to_world_pos(g.pos_vs);
  vec2 uv[2];
  bool ok[2];
  float expected_depth, unused_depth;
  // Surface: the motion vector (moving objects included), checked against the depth the point
  // had from last frame's camera.
  uv[0] = (vec2(p) + 0.5 + texelFetch(motion_tex, p, 0).xy) * frame.viewport.zw;
  vec2 unused_uv;
  ok[0] = valid && previous_uv(world, unused_uv, expected_depth) && same_surface(uv[0], g, expected_depth);
  // Parallax: the reflected point's virtual image, mean hit length behind the surface along the
  // view ray.
  vec3 virtual_point = world + view_to_world_dir(normalize(g.pos_vs)) * stats.g;
  ok[1] = valid && stats.g > 0.0 && previous_uv(virtual_point, uv[1], unused_depth) && same_surface(uv[1], g, -1.0);

  // Of the valid candidates, the one whose history lies nearest this frame's neighbourhood
  // (in its luminance spread); the surface one on a tie.
  vec4 history = vec4(0.0);
  vec2 history_stats_value = vec2(0.0);
  bool reprojected = false;
  float best = 1e30;
  float sigma_lum = max(luminance(sigma.rgb), 1e-4);
  for (int i = 0; i < 2; ++i) {
    vec4 h;
    vec2 hs;
    if (!ok[i] || !history_at(uv[i], h, hs)) continue;
    float distance_to_mean = abs(luminance(h.rgb - mean.rgb)) / sigma_lum;
    if (distance_to_mean < best) {
      best = distance_to_mean;
      history = h;
      history_stats_value = hs;
      reprojected = true;
    }
  }
  result = current;
  float variance = stats.r;
  float frames = 1.0;
  if (reprojected && history_stats_value.g >= 1.0) {
    // The box always holds this frame's own value: a pixel unlike its neighbours (an edge, a
    // sharp highlight) keeps its history instead of being pulled to the neighbourhood's mean.
    float gamma = pass.params.clip_gamma;
    history = clamp(history, min(mean - gamma * sigma, current), max(mean + gamma * sigma, current));
    frames = min(history_stats_value.g + 1.0, float(max(pass.params.history, 1)));
    result = mix(history, current, 1.0 / frames);
    variance = mix(stats.r, history_stats_value.r, clamp(pass.params.variance_stability, 0.0, 1.0));
  }
  out_stats_value = vec2(variance, frames);
}
