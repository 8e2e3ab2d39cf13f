// Tile classification's per-texel work (include-only; render/classify.comp is the pass, which
// provides `params` (ClassifyParams), glass_surface_tex and the output images).

// CLASS_TRACED here means "may trace"; main() decides which of those do this frame.
uint pixel_class(ivec2 p, out float roughness) {
  GSample g = gbuffer_fetch(p);
  roughness = g.roughness;
  if (!is_reflective(g)) return CLASS_NONE;
  if (g.roughness > params.roughness_threshold) return CLASS_ENVIRONMENT;
  return CLASS_TRACED;
}

// Classifies the pixels trace texel t stands for and writes their classes (or, for a tracer's
// own list, the outputs of the pixels without work); `traces`: one of them traces this frame (a
// reflection, or with list_glass a refraction: the tile list holds its tile), `listed`: the
// texel goes into the ray list.
void classify_texel(ivec2 t, out bool traces, out bool listed) {
  traces = false;
  listed = false;
  if (any(greaterThanEqual(t, params.trace_size.xy))) return;
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
      if (glass) traces = true;
      bool pixel_listed = c == CLASS_TRACED || glass;
      listed = listed || pixel_listed;
#ifdef CLASSIFY_FOR_TRACER
      if (!pixel_listed) {
        imageStore(out_reflection, p, vec4(0.0));
#ifdef SSR_DEBUG_IMAGE
        imageStore(out_debug, p, vec4(0.0));
#endif
      }
#else
      imageStore(out_class, p, vec4(float(c) / CLASS_LEVELS));
#endif
      if (params.list_glass != 0 && !pixel_listed) imageStore(out_refraction, p, vec4(0.0));
    }
}
