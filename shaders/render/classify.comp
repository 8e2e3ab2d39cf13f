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

// CLASS_TRACED here means "may trace"; main() decides which of those do this frame.
uint pixel_class(ivec2 p, out float roughness) {
  GSample g = gbuffer_fetch(p);
  roughness = g.roughness;
  if (!is_reflective(g)) return CLASS_NONE;
  if (g.roughness > params.roughness_threshold) return CLASS_ENVIRONMENT;
  return CLASS_TRACED;
}

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    tile_traces = false;
    group_rays = 0u;
  }
  barrier();
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  bool traces = false, listed = false;
  if (all(lessThan(t, params.trace_size.xy))) {
    int d = params.divisor;
    ivec2 chosen = t * d + params.trace_size.zw;
    int frame_index = frame.counts.z;
    for (int y = 0; y < d; ++y)
      for (int x = 0; x < d; ++x) {
        ivec2 p = t * d + ivec2(x, y);
        if (any(greaterThanEqual(p, ivec2(frame.viewport.xy)))) continue;
        float roughness;
        uint c = pixel_class(p, roughness);
        if (c == CLASS_TRACED) {
          // Half resolution: the block's pixel of this frame traces. Full resolution: glossy
          // pixels above quad_roughness trace `rays_per_quad` of each quad.
          bool own = d == 2 ? p == chosen
                            : (roughness <= params.quad_roughness ||
                               quad_traces(p, frame_index, params.rays_per_quad));
          if (own) traces = true; else c = CLASS_REUSED;
        }
        bool glass = params.list_glass != 0 && texelFetch(glass_surface_tex, p, 0).w >= 1.0;
        bool pixel_listed = c == CLASS_TRACED || glass;
        listed = listed || pixel_listed;
#ifdef CLASSIFY_FOR_TRACER
        if (!pixel_listed) {
          imageStore(out_reflection, p, vec4(0.0));
          imageStore(out_debug, p, vec4(0.0));
        }
#else
        imageStore(out_class, p, vec4(float(c) / CLASS_LEVELS));
#endif
        if (params.list_glass != 0 && !pixel_listed) imageStore(out_refraction, p, vec4(0.0));
      }
  }
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
