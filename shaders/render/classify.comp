// Tile classification (src/render/classification.h): one invocation per trace texel, one work
// group per tile. Each invocation classifies the pixels its texel stands for (1 or 2x2); the
// group appends its tile to the tile list when any of its texels traces, and its tracing texels
// to the ray list.
//
// Built with CLASSIFY_FOR_TRACER (a tracer's own trace, render/classification.h): no class
// image; a pixel without work gets here what the tracer would have written there (nothing
// reflected, no debug values), so the trace runs on the ray list alone. With list_glass, pixels
// behind glass are listed too (the tracers refract), and the others get no refraction here.
#include "common/gbuffer.glsl"
#include "shared/classification.h"

layout(local_size_x = CLASSIFY_TILE, local_size_y = CLASSIFY_TILE) in;
layout(std140, binding = UBO_PASS) uniform ClassifyBlock { ClassifyParams params; };
layout(std430, binding = SSBO_TILES) buffer Tiles {
  TileListHeader header;
  uint tiles[];
};
layout(std430, binding = SSBO_RAYS) buffer Rays {
  RayListHeader ray_header;
  uint rays[];
};
layout(binding = TEX_GLASS_SURFACE) uniform sampler2D glass_surface_tex;  // read with list_glass only
#ifdef CLASSIFY_FOR_TRACER
layout(binding = IMG_OUT, rgba16f) uniform writeonly image2D out_reflection;
layout(binding = IMG_OUT2, rgba16f) uniform writeonly image2D out_debug;
#else
layout(binding = IMG_OUT, r8) uniform writeonly image2D out_class;
#endif
layout(binding = IMG_REFRACTION, rgba16f) uniform writeonly image2D out_refraction;  // with list_glass

shared bool tile_traces;
shared uint group_rays;
shared uint group_base;

#include "common/classify.glsl"

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    tile_traces = false;
    group_rays = 0u;
  }
  barrier();
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  bool traces, listed;
  classify_texel(t, traces, listed);
  // The ray list costs a word per texel and two global atomics per tile: only when asked for.
  listed = listed && params.list_rays != 0;
  uint slot = 0u;
  if (traces) tile_traces = true;
  if (listed) slot = atomicAdd(group_rays, 1u);
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (tile_traces) {
      uint tile_slot = atomicAdd(header.groups_x, 1u);
      tiles[tile_slot] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16u);
    }
    if (group_rays > 0u) {
      group_base = atomicAdd(ray_header.count, group_rays);
      atomicMax(ray_header.groups_x, (group_base + group_rays + uint(RAY_LIST_GROUP) - 1u) / uint(RAY_LIST_GROUP));
    }
  }
  barrier();
  if (listed) rays[group_base + slot] = pack_texel(t);
}
