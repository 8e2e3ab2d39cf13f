// The shared tracer options (shaders/shared/ray_options.h), described once: every tracer's
// table is its own parameters followed by these, under its own key prefix ("dda.samples", ...).
#pragma once
#include <cstddef>
#include <initializer_list>
#include <vector>

#include "shared/ray_options.h"
#include "core/params.h"
#include "techniques/denoiser.h"

namespace ssr {

// The rows a rough-reflection technique shares whatever its Params (the tracers' RayOptions,
// ppr's own fields): one description each, at the member's offset.
inline ParamDesc samples_row(std::size_t offset) {
  return {"samples", ParamType::Int, offset, 1, 16, 1, "rays", "GGX VNDF rays per rough pixel (mirror pixels trace one)."};
}
inline ParamDesc roughness_row(std::size_t offset) {
  return with_auto({"roughness", ParamType::Float, offset, 0, 1, 0.01, "",
                    "Override the G-buffer roughness everywhere (auto keeps each material's)."},
                   -1.0);
}
inline ParamDesc seed_row(std::size_t offset) {
  return {"seed", ParamType::Int, offset, 0, 1000000, 1, "", "Random seed of the rough samples and the jitter."};
}

// The shared rows for a Params struct P whose member `ray` is a RayOptions. `with_blend` adds
// the Roberts blend switch (only linear-binary offers it).
template <class P>
std::vector<ParamDesc> with_ray_options(std::initializer_list<ParamDesc> own, bool with_blend = false) {
  using R = shared::RayOptions;
  const std::size_t base = offsetof(P, ray);
  auto at = [base](ParamDesc d, std::size_t field) {
    d.offset = base + field;
    d.group = "ray options";
    return d;
  };
  std::vector<ParamDesc> t(own);
  t.push_back(at(samples_row(0), offsetof(R, samples)));
  t.push_back(at(roughness_row(0), offsetof(R, roughness)));
  t.push_back(at({"backface_thickness", ParamType::Bool, 0, 0, 1, 1, "",
                  "Thickness from a back-face depth buffer: a hit lies between front and back faces."},
                 offsetof(R, backface_thickness)));
  t.push_back(at({"falloff_distance", ParamType::Float, 0, 0, 1000, 0.5, "world units",
                  "Confidence fades to zero towards this ray length (0 = no falloff)."}, offsetof(R, falloff_distance)));
  t.push_back(at(with_auto({"edge_fade", ParamType::Bool, 0, 0, 1, 1, "",
                            "Fade confidence towards the screen edges: clamp(1 - |u-0.5| - |v-0.5|, 0, 1) (Roberts); "
                            "auto: on with the Roberts blend only."}, -1),
                 offsetof(R, edge_fade)));
  t.push_back(at({"fresnel", ParamType::Bool, 0, 0, 1, 1, "",
                  "Roberts blend only: weight by Schlick Fresnel (the standard composite always applies it)."},
                 offsetof(R, fresnel)));
  if (with_blend) {  // linear-binary's own (only it offers the switch), though RayOptions holds it
    ParamDesc blend = at({"blend", ParamType::Choice, 0, 0, 1, 1, "",
                          "standard: lit + specular * mix(env, refl, conf); roberts: mix(lit, refl, metallic^3 * -ray.z * fade).",
                          {"standard", "roberts"}}, offsetof(R, blend));
    blend.group = "";
    t.push_back(blend);
  }
  t.push_back(at(seed_row(0), offsetof(R, seed)));
  t.push_back(at({"compact", ParamType::Bool, 0, 0, 1, 1, "",
                  "Trace only the pixels with work: the tile classification lists them (and those behind glass) "
                  "and the trace runs one lane per listed pixel (indirect dispatch); off: one lane per screen pixel "
                  "(faster on every scene measured: docs/RESULTS.md, Speed)."},
                 offsetof(R, compact)));
  for (const ParamDesc& d : denoise_options(base + offsetof(R, denoise), /*with_switch=*/true)) t.push_back(d);
  return t;
}

}  // namespace ssr
