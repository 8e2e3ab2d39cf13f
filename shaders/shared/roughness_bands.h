// Roughness bands on perceptual roughness: mirror < 0.05 <= glossy <= 0.4 < rough, for the
// verdicts' regions (eval/breakdown.h), compared on the roughness as the G-buffer holds it, a half
// float (0.05 is 0.049988 there), with the bounds rounded the same way: a material authored at
// 0.05 (corridor's floor, pedestal's chrome) is glossy. The denoiser's spatial stage reuses rays
// by the BRDF only above the stored mirror bound (denoise/spatial.comp says why).
#pragma once
#include "shared/interop.h"

#define MIRROR_BAND_BELOW 0.05
#define ROUGH_BAND_ABOVE 0.4

SSR_SHARED_BEGIN

// r as the G-buffer's half float holds it (0.05 and 0.4 round the same to nearest or towards 0).
SSR_FN float as_stored_roughness(float r) { return unpackHalf2x16(packHalf2x16(vec2(r, 0.0f))).x; }

SSR_SHARED_END
