// Pixel-Projected Reflections (Kim 2018 after Cichocki 2017): parameters and reflector layout,
// shared by src/techniques/ppr.cpp and shaders/techniques/ppr_*.comp.
#pragma once
#include "shared/bindings.h"
#include "shared/interop.h"

SSR_SHARED_BEGIN

#define PPR_MAX_REFLECTORS 16

struct PprParams {
  int hole_fill SSR_DEFAULT(2);       // 0: none, 1: 4 neighbours, 2: 8 neighbours
  int samples SSR_DEFAULT(1);         // GGX VNDF samples for rough reflectors (1..16)
  float roughness SSR_DEFAULT(-1.0f); // < 0: the G-buffer's roughness; else used everywhere
  int normal_maps SSR_DEFAULT(1);     // 1: perturbed normals (reflection distance x perturbed ray, reprojected)
  int edge_fade SSR_DEFAULT(0);       // 1: confidence fades towards the screen edges
  int seed SSR_DEFAULT(0);            // random seed of the per-pixel sample rotation
  int reflector_count SSR_DEFAULT(0); // set by the technique from the scene (not a parameter)
  int fallback SSR_DEFAULT(4);        // tracer for what projection cannot serve: 0 none, 1 linear, 2 linear-binary, 3 dda, 4 hiz
};

// One planar reflector, oriented for the frame: `plane.xyz` faces the camera.
struct PprReflector {
  vec4 plane;      // world n.xyz (unit, towards the camera), d: dot(n, x) + d = 0 on the plane
  vec4 center;     // world centre; w: one past the last of the consecutive reflectors on this plane (an index)
  vec4 tangent;    // unit tangent, w = half extent along it
  vec4 bitangent;  // unit bitangent, w = half extent along it
};

SSR_SHARED_END
