#include "core/errors.h"
#include "registry/registry.h"

namespace ssr {

// One line per technique; each factory lives in its technique's file.
std::unique_ptr<Technique> make_none_technique();
std::unique_ptr<Technique> make_linear_technique();
std::unique_ptr<Technique> make_linear_binary_technique();
std::unique_ptr<Technique> make_dda_technique();
std::unique_ptr<Technique> make_hiz_technique();
std::unique_ptr<Technique> make_ppr_technique();
std::unique_ptr<Technique> make_stochastic_technique();
std::unique_ptr<Technique> make_reference_technique();
std::unique_ptr<Technique> make_planar_technique();

const std::vector<TechniqueInfo>& technique_registry() {
  // The descriptions are the README's technique table (`ssrlab techniques --markdown`).
  static const std::vector<TechniqueInfo> registry = {
      {"none",
       "no reflection work: the composite shows the environment",
       make_none_technique},
      {"linear",
       "brute-force view-space march (Kim 2018 §2.3.1), optional depth interpolation [Val14]",
       make_linear_technique},
      {"linear-binary",
       "Roberts: linear march + binary refinement, edge fade, optional Roberts blend",
       make_linear_binary_technique},
      {"dda",
       "McGuire & Mara: perspective-correct per-pixel screen-space DDA, near-plane clipping, "
       "stride, jitter, refinement",
       make_dda_technique},
      {"hiz",
       "Hi-Z: a depth pyramid (max = closest, odd sizes handled) traversed hierarchically",
       make_hiz_technique},
      {"ppr",
       "Pixel-Projected Reflections (Kim 2018 after Cichocki 2017): pixels projected across each "
       "planar reflector with `imageAtomicMin` into an r32ui image, resolved with hole patching and "
       "each pixel's own mirror ray refined on the source's tangent plane; "
       "normal maps and GGX samples by reprojection; `fallback` (default `hiz`) traces the "
       "reflective pixels projection cannot serve (non-planar surfaces, unfilled holes, rays that "
       "pass a source's outline or meet a nearer surface first, normal-mapped mirror pixels), `none` is the thesis's technique",
       make_ppr_technique},
      {"stochastic",
       "stochastic SSR as engines ship it (Diligent's document, AMD FidelityFX SSSR): tile "
       "classification (roughness threshold, 1/2/4 rays per quad, half resolution) feeding an "
       "indirect dispatch; one GGX VNDF ray per traced pixel from a spatio-temporal blue-noise "
       "texture ssrlab makes itself (void-and-cluster, `core/blue_noise.h`), GGX bias, Hi-Z "
       "trace, optional previous-frame hits; then the denoiser",
       make_stochastic_technique},
      {"reference",
       "ground truth: Embree traces the true rays (GGX VNDF samples on rough pixels; glass "
       "pixels refract with the tracers' single-interface model), the GPU shades the hits with "
       "the lit pass's code, normal maps included; `bounces` N follows reflective hits N-1 more "
       "times (1: a mirror seen in a mirror is black)",
       make_reference_technique, /*truth=*/true, /*on_demand=*/true},
      {"planar",
       "the classic mirrored-camera render of each planar reflector: a second, independent "
       "oracle for flat mirrors (roughness and normal maps ignored: sharp on a rough floor)",
       make_planar_technique, /*truth=*/false, /*on_demand=*/false, /*oracle=*/true},
  };
  return registry;
}

const TechniqueInfo& technique_info(const std::string& name) {
  std::string known;
  for (const TechniqueInfo& t : technique_registry()) {
    if (t.name == name) return t;
    known += (known.empty() ? "" : ", ") + t.name;
  }
  throw InputError("unknown technique '" + name + "' (known: " + known + ").");
}

std::unique_ptr<Technique> create_technique(const std::string& name) { return technique_info(name).create(); }

std::vector<std::string> oracle_names() {
  std::vector<std::string> names;
  for (const TechniqueInfo& t : technique_registry())
    if (t.oracle) names.push_back(t.name);
  return names;
}

bool is_truth(const std::string& name) { return name == truth_name(); }

const std::string& truth_name() {
  static const std::string name = [] {
    for (const TechniqueInfo& t : technique_registry())
      if (t.truth) return t.name;
    return std::string();
  }();
  return name;
}

}  // namespace ssr
