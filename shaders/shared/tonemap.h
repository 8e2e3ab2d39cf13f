// Output transform shared by GLSL (display pass) and C++ (metrics): one definition, so the error
// metrics see exactly the numbers the PNGs show. Written in the common subset of GLSL and GLM.
#pragma once
#include "shared/interop.h"

SSR_SHARED_BEGIN

// ACES filmic fit (Narkowicz 2015); input is linear radiance scaled by the exposure.
SSR_FN vec3 tonemap_aces(vec3 x) {
  x = max(x, vec3(0.0f));
  return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), vec3(0.0f), vec3(1.0f));
}

SSR_FN vec3 linear_to_srgb(vec3 c) {
  c = clamp(c, vec3(0.0f), vec3(1.0f));
  return mix(c * 12.92f, 1.055f * pow(c, vec3(1.0f / 2.4f)) - 0.055f, step(vec3(0.0031308f), c));
}

// Linear HDR radiance -> displayed value in [0,1] (what the PNG stores, before quantisation).
SSR_FN vec3 display_transform(vec3 radiance, float exposure_stops) {
  return linear_to_srgb(tonemap_aces(radiance * exp2(exposure_stops)));
}

SSR_SHARED_END
