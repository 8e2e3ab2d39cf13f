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
  static const std::vector<TechniqueInfo> registry = {
      {"none", "no reflections: the composite shows the environment only", make_none_technique},
      {"linear", "brute-force view-space linear march (Kim 2018, 2.3.1), optional depth interpolation",
       make_linear_technique},
      {"linear-binary", "Roberts: view-space linear march + binary search refinement, edge fade, optional Roberts blend",
       make_linear_binary_technique},
      {"dda", "McGuire & Mara: perspective-correct per-pixel screen-space DDA with stride, jitter and refinement", make_dda_technique},
      {"hiz", "Hi-Z: hierarchical depth-pyramid tracing (max = closest for reversed-Z) with an iteration cap", make_hiz_technique},
      {"ppr", "Pixel-Projected Reflections: planar reflectors by projection (imageAtomicMin), hole patching",
       make_ppr_technique},
      {"stochastic",
       "stochastic SSR (Diligent, FidelityFX SSSR): tile classification, 1 blue-noise GGX ray per pixel through Hi-Z, "
       "spatial/temporal/bilateral denoiser",
       make_stochastic_technique},
      {"reference", "ground truth: Embree ray tracing of the true reflection rays, shaded with the lit pass's code",
       make_reference_technique, /*truth=*/true, /*on_demand=*/true},
      {"planar", "planar-mirror oracle: the scene rendered from the camera mirrored across each reflector",
       make_planar_technique},
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

}  // namespace ssr
