// Layouts of the ground truth's GPU shading pass (C++ traces with Embree, the GPU shades the hits
// with the lit pass's own shade_surface, seen from the ray).
#pragma once
#include "shared/bindings.h"
#include "shared/interop.h"

SSR_SHARED_BEGIN


// One ray segment. A sample is `bounces` consecutive segments (segment 0: the reflection ray;
// segment b: the reflection of segment b-1's hit, present only where that hit is reflective).
struct ReferenceSample {
  vec4 position;   // xyz: world hit position; w: material index, -1 when the ray escaped, -2 for
                   //      an unused segment (the path ended before it)
  vec4 normal;     // xyz: unit world shading normal facing the ray; w: log2 of the texture
                   //      footprint in uv units (ray cone), before the texture's size is added
  vec4 direction;  // xyz: unit ray direction (away from the reflecting point); w: 1 when the hit
                   //      is traceable (visible on screen), else 0
  vec4 hit_pixel;  // xy: the hit's pixel (GL convention, for the screen-space ideal; segment 0
                   //      only); zw: uv
  vec4 tangent;    // xyz: world tangent along +u at the hit (for normal maps); w: handedness
};

struct ReferencePixel {
  ivec4 data;      // x, y: pixel; z: first sample; w: sample count (0: not reflective)
};

struct ReferenceMaterial {
  vec4 albedo_metallic;  // linear albedo, metallic
  vec4 params;           // roughness, reflectance, albedo texture slot, normal map slot (-1: none)
  vec4 emission;         // linear rgb, normal map strength
};

SSR_SHARED_END
