// What each view shows at pixel p (include-only; render/display.comp is the pass, which
// provides u_view and the textures named here). `hdr`: radiance to tone map; otherwise data
// shown as it is (clamped). Heat maps and category colours come from shared/colormap.h, the
// functions the viewer's legends draw with.

vec3 display_view(ivec2 p, out bool hdr) {
  hdr = true;
  vec3 v = vec3(0.0);
  if (u_view == VIEW_FINAL) {
    v = texelFetch(color_tex, p, 0).rgb;
  } else if (u_view == VIEW_REFLECTION) {
    v = texelFetch(reflection_tex, p, 0).rgb;
  } else if (u_view == VIEW_RAW || u_view == VIEW_SPATIAL || u_view == VIEW_TEMPORAL) {
    v = textureLod(stage_tex, pixel_to_uv(p), 0.0).rgb;
  } else if (u_view == VIEW_LIT) {
    v = texelFetch(lit_tex, p, 0).rgb;
  } else if (u_view == VIEW_REFLECTED) {
    // What the standard composite multiplies by the specular weight (the error a technique
    // makes before a dielectric's small F0 hides it); black off the reflective pixels.
    GSample g = gbuffer_fetch(p);
    if (texelFetch(glass_surface_tex, p, 0).w >= 1.0) {
      // Through glass: the refracted radiance the composite tints (the unbent background where
      // the technique found none).
      vec4 refr = texelFetch(refraction_tex, p, 0);
      v = mix(texelFetch(lit_tex, p, 0).rgb, refr.rgb, clamp(refr.a, 0.0, 1.0));
    } else if (is_reflective(g)) {
      vec4 refl = texelFetch(reflection_tex, p, 0);
      vec3 env = environment_radiance(view_to_world_dir(reflect(normalize(g.pos_vs), g.n_vs)));
      v = mix(env, refl.rgb, clamp(refl.a, 0.0, 1.0));
    }
  } else {
    hdr = false;
    GSample g = gbuffer_fetch(p);
    bool bg = is_background(g.depth);
    if (u_view == VIEW_CONFIDENCE) v = vec3(clamp(texelFetch(reflection_tex, p, 0).a, 0.0, 1.0));
    else if (u_view == VIEW_NORMAL) v = bg ? vec3(0.0) : g.n_vs * 0.5 + 0.5;
    else if (u_view == VIEW_DEPTH) {
      float z = bg ? frame.clip.y : -g.pos_vs.z;
      v = vec3(1.0 - log(z / frame.clip.x) / log(frame.clip.y / frame.clip.x));
    }
    else if (u_view == VIEW_ALBEDO) v = g.albedo;
    else if (u_view == VIEW_ROUGHNESS) v = vec3(g.roughness);
    else if (u_view == VIEW_METALLIC) v = vec3(g.metallic);
    else if (u_view == VIEW_STEPS) v = heat(texelFetch(debug_tex, p, 0).x / HEAT_STEPS_FULL);
    else if (u_view == VIEW_HITS) v = vec3(texelFetch(debug_tex, p, 0).y);
    else if (u_view == VIEW_DISTANCE) v = heat(texelFetch(debug_tex, p, 0).z / HEAT_DISTANCE_FULL);
    else if (u_view == VIEW_OFFSETS) v = vec3(0.5 + texelFetch(debug_tex, p, 0).xy * frame.viewport.zw, 0.5);
    else if (u_view == VIEW_HOLES) v = vec3(texelFetch(debug_tex, p, 0).zw, 0.0);
    else if (u_view == VIEW_MOTION) {
      vec2 m = texelFetch(motion_tex, p, 0).xy;
      float len = length(m);
      v = len > 1e-4 ? hue(atan(m.y, m.x)) * clamp(len / MOTION_FULL_PIXELS, 0.0, 1.0) : vec3(0.0);
    }
    else if (u_view == VIEW_CLASSES) {
      v = tile_class_colour(clamp(int(textureLod(stage_tex, pixel_to_uv(p), 0.0).r * CLASS_LEVELS + 0.5), 0, 3));
    }
    else if (u_view == VIEW_RAY_LENGTH) v = heat(textureLod(stage_tex, pixel_to_uv(p), 0.0).g / HEAT_DISTANCE_FULL);
    else if (u_view == VIEW_VARIANCE) v = heat(sqrt(max(textureLod(stage_tex, pixel_to_uv(p), 0.0).r, 0.0)));
    else if (u_view == VIEW_HISTORY) v = heat(textureLod(stage_tex, pixel_to_uv(p), 0.0).g / HEAT_HISTORY_FULL);
    else if (u_view == VIEW_ITERATIONS || u_view == VIEW_IDLE_LANES) {
      uint word = telemetry_pixels[p.y * int(telemetry.width) + p.x];
      v = word == 0u ? vec3(0.0)
                     : heat(u_view == VIEW_ITERATIONS ? float(telemetry_iterations(word)) / HEAT_ITERATIONS_FULL : telemetry_idle(word));
    }
    else if (u_view == VIEW_MASK) v = mask_colour(is_reflective(g), g.reflector > 0u);
  }
  return v;
}
