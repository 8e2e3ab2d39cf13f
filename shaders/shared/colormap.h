// Colour maps shared by the display pass, the viewer's difference view (GLSL) and the viewer's
// legends (C++): the colour bar a user reads is the function the image was drawn with.
#pragma once
#include "shared/interop.h"

// Full scales of the heat-map views (the value drawn as the hottest colour; above it clamps).
#define HEAT_STEPS_FULL 256.0f       // VIEW_STEPS: iterations per ray
#define HEAT_DISTANCE_FULL 20.0f     // VIEW_DISTANCE, VIEW_RAY_LENGTH: world units
#define HEAT_HISTORY_FULL 32.0f      // VIEW_HISTORY: frames accumulated
#define HEAT_ITERATIONS_FULL 128.0f  // VIEW_ITERATIONS: trace iterations over the pixel's rays
#define MOTION_FULL_PIXELS 16.0f     // VIEW_MOTION: the length shown at full brightness

SSR_SHARED_BEGIN

// Black -> purple -> orange -> yellow over t in [0, 1] (clamped).
SSR_FN vec3 heat(float t) {
  t = clamp(t, 0.0f, 1.0f);
  return clamp(vec3(1.6f * t, 1.6f * t * t, 0.5f * sin(3.14159f * t) + 0.2f * t * t * t), vec3(0.0f), vec3(1.0f));
}

// Full-saturation hue of an angle in radians (0 = red, 2pi/3 = green, 4pi/3 = blue).
SSR_FN vec3 hue(float a) {
  return clamp(abs(fract(a / 6.28318530718f + vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f) - 1.0f, vec3(0.0f),
               vec3(1.0f));
}

// VIEW_CLASSES: 0 none, 1 environment only, 2 traced, 3 reused.
SSR_FN vec3 tile_class_colour(int c) {
  return c <= 0 ? vec3(0.0f) : c == 1 ? vec3(0.2f, 0.35f, 1.0f) : c == 2 ? vec3(0.2f, 0.85f, 0.3f) : vec3(1.0f, 0.85f, 0.2f);
}

// VIEW_MASK: black off the reflective pixels, white on them, tinted on planar reflectors.
SSR_FN vec3 mask_colour(bool reflective, bool planar) {
  return !reflective ? vec3(0.0f) : planar ? vec3(1.0f, 0.85f, 0.3f) : vec3(1.0f);
}

SSR_SHARED_END
