// `linear`: the brute-force screen-space reflection of the PPR thesis (Kim 2018, 2.3.1).
// March the view-space reflection ray in fixed steps, project each sample, stop at the first
// sample behind the depth buffer by less than the thickness. Optional depth interpolation
// ([Val14], thesis fig. 8) places the hit between the last two samples.
#include "shared/linear.h"
#include "techniques/tracer.h"

#include <algorithm>

namespace ssr {
namespace {

using P = shared::LinearParams;
const std::vector<ParamDesc> kTable = with_ray_options<P>({
    SSR_PARAM_INT(P, max_steps, 1, 8192, "steps", "Number of march iterations per ray."),
    with_auto(SSR_PARAM_FLOAT(P, step_size, 0.001, 50.0, 0.01, "world units",
                              "Distance between two samples along the reflected ray; auto: max_distance / max_steps, "
                              "so that the march reaches max_distance.")),
    SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                    "A sample this far or less behind the depth buffer counts as a hit."),
    with_auto(SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 1.0, "world units",
                              "Rays stop after this distance from the reflecting point; auto: the scene's bounding-box diagonal.")),
    SSR_PARAM_BOOL(P, depth_interp,
                   "Refine the hit by linearly interpolating ray and buffer depths between the last two samples."),
});

// 256 steps of 0.1 reached 25.6 m at most and left gallery 4.4 dB short of 4x finer steps.
void resolve(P& p, const AutoContext& c) {
  if (p.max_distance == 0.0f) p.max_distance = c.max_distance();
  if (p.step_size == 0.0f) p.step_size = std::max(p.max_distance / static_cast<float>(p.max_steps), 0.001f);
}

}  // namespace

std::unique_ptr<Technique> make_linear_technique() {
  return std::make_unique<TracerTechnique<P>>("linear", kTable, "techniques/linear.comp", resolve);
}

}  // namespace ssr
