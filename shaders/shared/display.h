// What the display pass shows (--view); the C++ enum and the GLSL switch share these numbers.
#pragma once
#include "shared/interop.h"

#define VIEW_FINAL 0        // composited colour, tone mapped
#define VIEW_REFLECTION 1   // technique reflection rgb, tone mapped
#define VIEW_CONFIDENCE 2   // technique reflection alpha, grey
#define VIEW_LIT 3          // lit colour without reflections, tone mapped
#define VIEW_NORMAL 4       // view-space normal * 0.5 + 0.5
#define VIEW_DEPTH 5        // linear view depth, near white -> far black (log scale)
#define VIEW_ALBEDO 6
#define VIEW_ROUGHNESS 7
#define VIEW_METALLIC 8
#define VIEW_MASK 9         // reflective pixels white, planar reflectors tinted
#define VIEW_STEPS 10       // tracer iterations per ray, heat map (0 .. 256+)
#define VIEW_HITS 11        // share of the pixel's rays that hit, grey
#define VIEW_DISTANCE 12    // mean hit distance, heat map (0 .. 20 world units)
#define VIEW_OFFSETS 13     // PPR: decoded offset to the source pixel as colour (0.5 = none)
#define VIEW_HOLES 14       // PPR: red = hole patched, green = projection refused (fallback), yellow = no source
#define VIEW_REFLECTED 15   // what the composite weights: mix(env, reflection.rgb, a); through glass mix(lit, refraction.rgb, a)
#define VIEW_MOTION 16     // motion vectors (G-buffer): hue = direction, brightness = length
// Stage views: a technique texture at TEX_STAGE_VIEW (TechniqueDecl::stage_views)
#define VIEW_CLASSES 17     // classification: black none, blue environment, green traced, yellow reused
#define VIEW_RAW 18         // the trace's radiance (premultiplied by confidence), tone mapped
#define VIEW_RAY_LENGTH 19  // mean hit length after spatial reuse, heat map (0 .. 20 world units)
#define VIEW_SPATIAL 20     // after spatial reconstruction, tone mapped
#define VIEW_TEMPORAL 21    // after temporal accumulation, tone mapped
#define VIEW_VARIANCE 22    // luminance variance estimate (r), sqrt as a heat map (0 .. 1)
#define VIEW_HISTORY 23     // frames accumulated (g), heat map (0 .. 32)
#define VIEW_ITERATIONS 24  // telemetry: the lane's iterations over all its rays, heat map (0 .. 128+)
#define VIEW_IDLE_LANES 25  // telemetry: the idle share of the pixel's warp, heat map (0 .. 1)
#define VIEW_COUNT 26
