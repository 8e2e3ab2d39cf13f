// Motion vectors (shared/frame.h): pixels from this frame's position to the previous frame's.
// Needs common/frame.glsl.

// A point's clip positions now and in the previous frame -> motion in pixels. A previous
// position behind the camera (w <= 0) has no screen position: no motion is claimed (0) rather
// than a huge or flipped vector.
vec2 motion_pixels(vec4 clip, vec4 prev_clip) {
  if (prev_clip.w <= 1e-6 || clip.w <= 1e-6) return vec2(0.0);
  vec2 now = clip.xy / clip.w, before = prev_clip.xy / prev_clip.w;
  return (before - now) * 0.5 * frame.viewport.xy;
}
