// PPR's projection (include-only): one source pixel mirrored across one planar reflector, and
// the packed offset back to it splatted into the destination pixels that see it there.
//
// The pass provides (techniques/ppr_project.comp): `intermediate` (r32ui, atomic min) and
// `u_fraction_bits`.

// How the mirror image moves on screen per source pixel (columns: source +x, +y), to first
// order from the source's tangent plane (its neighbours' eye rays); false where degenerate.
bool mirror_jacobian(GSample g, ivec2 p, vec2 dest, PprReflector r, out mat2 jacobian) {
  jacobian = mat2(1.0);
  for (int a = 0; a < 2; ++a) {
    vec3 ray = normalize(view_position(pixel_to_uv(p + (a == 0 ? ivec2(1, 0) : ivec2(0, 1))), 0.5));
    float denom = dot(ray, g.n_vs);
    if (abs(denom) < 1e-4) return false;
    vec2 moved;
    if (!mirror_to_pixel(ray * (dot(g.pos_vs, g.n_vs) / denom), r, moved)) return false;
    jacobian[a] = moved - dest;
  }
  return abs(determinant(jacobian)) >= 1e-6;
}

// Where the camera sees the mirror image of world point `x` across `plane`: the camera ray
// towards the image crosses the plane at t in (0, 1), at `hit`; false behind the mirror.
bool ppr_mirror_crossing(vec3 x, vec4 plane, out vec3 hit) {
  vec3 n = plane.xyz;
  float dist = dot(n, x) + plane.w;  // > 0: in front of the mirror
  vec3 mirrored = x - 2.0 * dist * n;
  vec3 eye = frame.camera_pos.xyz;
  float e = dot(n, eye) + plane.w;  // > 0: the technique orients planes towards the camera
  float t = e / (e - dot(n, mirrored) - plane.w);
  hit = eye + t * (mirrored - eye);
  return dist > 0.0 && t > 0.0 && t < 1.0;
}

// Where on screen the camera sees world point `hit` (continuous pixel coordinates); false off
// screen.
bool ppr_destination(vec3 hit, out vec2 dest) {
  vec2 uv;
  float depth;
  dest = vec2(0.0);
  if (!project_to_uv((frame.view * vec4(hit, 1.0)).xyz, uv, depth) || !uv_on_screen(uv)) return false;
  dest = uv * frame.viewport.xy;
  return true;
}

// Projects source pixel p (G-buffer g) through reflector k (r), whose plane the camera sees its
// mirror image through at `hit`; true when a destination pixel took it.
bool ppr_project_onto(ivec2 p, GSample g, int k, PprReflector r, vec3 hit) {
  vec3 local = hit - r.center.xyz;
  if (abs(dot(local, r.tangent.xyz)) > r.tangent.w || abs(dot(local, r.bitangent.xyz)) > r.bitangent.w)
    return false;  // outside the rectangle
  vec2 dest;
  if (!ppr_destination(hit, dest)) return false;
  ivec2 size = ivec2(frame.viewport.xy);
  ivec2 q = ivec2(dest);
  // The destination must show this reflector (not an occluder, not another reflector).
  if (texelFetch(g_material, q, 0).x != uint(k + 1)) return false;
  // Each destination pixel stores the offset from its centre back to the source point that
  // lands exactly there: source = this pixel + J^-1 (centre - dest). A mirror flips a screen
  // axis (a floor turns screen-up into screen-down), so the destination's fraction cannot be
  // added to the source as it is: that biased the source by up to a pixel along the flipped
  // axis (the dark line at the wall/floor junction). Where the mirror magnifies (a near
  // object's reflection), one source covers several destination pixels: it is splatted over
  // its footprint (at most 5x5), or the skipped pixels would keep a source from the wall
  // behind it (the stripes in the spheres' reflections).
  mat2 jacobian;
  bool exact = mirror_jacobian(g, p, dest, r, jacobian);
  mat2 to_source = exact ? inverse(jacobian) : mat2(0.0);
  // The footprint's half extent per axis is h; a neighbour n pixels away has its centre more
  // than n - 0.5 from `dest`, so it can lie inside only when n < h + 0.5.
  vec2 h = 0.5 * (abs(jacobian[0]) + abs(jacobian[1]));
  ivec2 reach = exact ? ivec2(min(max(ceil(h - 0.5), vec2(0.0)), vec2(2.0))) : ivec2(0);
  for (int dy = -reach.y; dy <= reach.y; ++dy)
    for (int dx = -reach.x; dx <= reach.x; ++dx) {
      ivec2 d = q + ivec2(dx, dy);
      if (any(lessThan(d, ivec2(0))) || any(greaterThanEqual(d, size))) continue;
      vec2 move = to_source * (vec2(d) + 0.5 - dest);
      // Only the destination pixels whose centre lies in this source pixel's footprint.
      if ((dx != 0 || dy != 0) && any(greaterThan(abs(move), vec2(0.5)))) continue;
      if ((dx != 0 || dy != 0) && texelFetch(g_material, d, 0).x != uint(k + 1)) continue;
      vec2 source = vec2(p) + 0.5 + clamp(move, vec2(-1.0), vec2(1.0));
      imageAtomicMin(intermediate, d, ppr_pack(source - (vec2(d) + 0.5), u_fraction_bits));
    }
  return true;
}
