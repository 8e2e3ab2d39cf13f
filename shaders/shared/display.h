// What the display pass shows (--view); the C++ enum and the GLSL switch share these numbers.
// What each view shows, its legend and scale: src/render/views.cpp (one description each, which
// `ssrlab views` and the README print), not restated here.
#pragma once
#include "shared/interop.h"

#define VIEW_FINAL 0
#define VIEW_REFLECTION 1
#define VIEW_CONFIDENCE 2
#define VIEW_LIT 3
#define VIEW_NORMAL 4
#define VIEW_DEPTH 5
#define VIEW_ALBEDO 6
#define VIEW_ROUGHNESS 7
#define VIEW_METALLIC 8
#define VIEW_MASK 9
#define VIEW_STEPS 10
#define VIEW_HITS 11
#define VIEW_DISTANCE 12
#define VIEW_OFFSETS 13
#define VIEW_HOLES 14
#define VIEW_REFLECTED 15
#define VIEW_MOTION 16
// Stage views: a technique texture at TEX_STAGE_VIEW (TechniqueDecl::stage_views).
#define VIEW_CLASSES 17
#define VIEW_RAW 18
#define VIEW_RAY_LENGTH 19
#define VIEW_SPATIAL 20
#define VIEW_TEMPORAL 21
#define VIEW_VARIANCE 22
#define VIEW_HISTORY 23
#define VIEW_ITERATIONS 24
#define VIEW_IDLE_LANES 25
#define VIEW_COUNT 26
