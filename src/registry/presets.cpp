#include "registry/presets.h"

#include "core/errors.h"
#include "techniques/technique.h"
#include "registry/registry.h"

namespace ssr {

const std::vector<Preset>& presets() {
  // The thesis's brute force compares against a depth threshold "according to the step size":
  // thickness = step size. Its max distance is whatever the steps reach.
  static const std::vector<Preset> list = {
      {"thesis-hq", "linear",
       {"linear.max_steps=1024", "linear.step_size=0.1", "linear.thickness=0.1",
        "linear.max_distance=10000", "linear.depth_interp=false"},
       "Kim 2018, fig. 25: brute force high quality, 1024 iterations, step 0.1"},
      {"thesis-lq", "linear",
       {"linear.max_steps=128", "linear.step_size=5", "linear.thickness=5",
        "linear.max_distance=10000", "linear.depth_interp=false"},
       "Kim 2018, fig. 26: brute force low quality, 128 iterations, step 5.0"},
      {"thesis-lq-interp", "linear",
       {"linear.max_steps=128", "linear.step_size=5", "linear.thickness=5",
        "linear.max_distance=10000", "linear.depth_interp=true"},
       "Kim 2018, fig. 29: low quality with depth linear interpolation"},
      {"roberts-default", "linear-binary",
       {"linear-binary.linear_steps=100", "linear-binary.binary_steps=10",
        "linear-binary.thickness=0.1", "linear-binary.max_distance=9", "linear-binary.edge_fade=true"},
       "Roberts: 100 linear + 10 binary steps, thickness 0.1, max distance 9, edge fade"},
      {"roberts-hq", "linear-binary",
       {"linear-binary.linear_steps=500", "linear-binary.binary_steps=10",
        "linear-binary.thickness=0.1", "linear-binary.max_distance=9", "linear-binary.edge_fade=true"},
       "Roberts: 500 linear + 10 binary steps, edge fade"},
      // Quality tiers of `stochastic` (rays, trace resolution, Hi-Z iterations, filter radius),
      // in the spirit of FidelityFX SSSR's presets.
      {"stochastic-low", "stochastic",
       {"stochastic.half_resolution=true", "stochastic.max_iterations=64", "stochastic.roughness_threshold=0.5",
        "stochastic.spatial_samples=4", "stochastic.spatial_radius=4", "stochastic.bilateral_radius=1"},
       "half-resolution trace, 64 Hi-Z iterations, rays below roughness 0.5, 4 reused rays, 3x3 bilateral"},
      {"stochastic-medium", "stochastic",
       {"stochastic.rays_per_quad=1", "stochastic.max_iterations=128", "stochastic.roughness_threshold=0.6",
        "stochastic.spatial_samples=6", "stochastic.spatial_radius=5", "stochastic.bilateral_radius=2"},
       "full resolution, 1 ray per 2x2 quad above roughness 0.3, 128 iterations, rays below roughness 0.6, "
       "6 reused rays"},
      {"stochastic-high", "stochastic",
       {"stochastic.rays_per_quad=4", "stochastic.roughness_threshold=1", "stochastic.spatial_samples=8",
        "stochastic.spatial_radius=6", "stochastic.bilateral_radius=2"},
       "the defaults: a ray per pixel at every roughness, auto iterations (128 on glossy rays), 8 reused rays"},
      {"stochastic-ultra", "stochastic",
       {"stochastic.rays_per_quad=4", "stochastic.roughness_threshold=1", "stochastic.glossy_iterations=auto",
        "stochastic.spatial_samples=16", "stochastic.spatial_radius=8", "stochastic.bilateral_radius=3",
        "stochastic.history=32"},
       "a ray per pixel at every roughness, auto iterations on every ray, 16 reused rays, 7x7 bilateral, "
       "32 frames of history"},
  };
  return list;
}

const Preset& find_preset(const std::string& name) {
  std::string known;
  for (const Preset& p : presets()) {
    if (p.name == name) {
      bool exists = false;
      for (const TechniqueInfo& t : technique_registry()) exists |= t.name == p.technique;
      if (!exists)
        throw InputError("preset '" + name + "' needs technique '" + p.technique +
                         "', which this build does not have yet.");
      return p;
    }
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw InputError("unknown preset '" + name + "' (known: " + known + ").");
}

}  // namespace ssr
