// Tile classification (src/render/classification.h): one invocation per trace texel, one work
// group per tile. Each invocation classifies the pixels its texel stands for (1 or 2x2) and the
// group appends its tile to the list when any of its texels traces.
#include "common/gbuffer.glsl"
#include "shared/classification.h"

layout(local_size_x = CLASSIFY_TILE, local_size_y = CLASSIFY_TILE) in;
layout(std140, binding = UBO_PASS) uniform ClassifyBlock { ClassifyParams params; };
layout(std430, binding = SSBO_TILES) buffer Tiles {
  TileListHeader header;
  uint tiles[];
};
layout(binding = IMG_OUT, r8) uniform writeonly image2D out_class;

shared bool tile_traces;

// CLASS_TRACED here means "may trace"; main() decides which of those do this frame.
uint pixel_class(ivec2 p, out float roughness) {
  GSample g = gbuffer_fetch(p);
  roughness = g.roughness;
  if (!is_reflective(g)) return CLASS_NONE;
  if (g.roughness > params.roughness_threshold) return CLASS_ENVIRONMENT;
  return CLASS_TRACED;
}

void main() {
  if (gl_LocalInvocationIndex == 0u) tile_traces = false;
  barrier();
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  bool traces = false;
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
        imageStore(out_class, p, vec4(float(c) / CLASS_LEVELS));
      }
  }
  if (traces) tile_traces = true;
  barrier();
  if (gl_LocalInvocationIndex == 0u && tile_traces) {
    uint slot = atomicAdd(header.groups_x, 1u);
    tiles[slot] = gl_WorkGroupID.x | (gl_WorkGroupID.y << 16u);
  }
}
