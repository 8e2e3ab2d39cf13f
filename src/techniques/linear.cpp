// `linear`: the brute-force screen-space reflection of the PPR thesis (Kim 2018, 2.3.1).
// March the view-space reflection ray in fixed steps, project each sample, stop at the first
// sample behind the depth buffer by less than the thickness. Optional depth interpolation
// ([Val14], thesis fig. 8) places the hit between the last two samples.
#include "shared/linear.h"
#include "techniques/tracer.h"

namespace ssr {
namespace {

using P = shared::LinearParams;
const std::vector<ParamDesc> kTable = with_ray_options<P>({
    SSR_PARAM_INT(P, max_steps, 1, 8192, "steps", "Number of march iterations per ray."),
    SSR_PARAM_FLOAT(P, step_size, 0.001, 50.0, 0.01, "world units",
                    "Distance between two samples along the reflected ray."),
    SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                    "A sample this far or less behind the depth buffer counts as a hit."),
    SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 1.0, "world units",
                    "Rays stop after this distance from the reflecting point."),
    SSR_PARAM_BOOL(P, depth_interp,
                   "Refine the hit by linearly interpolating ray and buffer depths between the last two samples."),
});

}  // namespace

std::unique_ptr<Technique> make_linear_technique() {
  return std::make_unique<TracerTechnique<P>>("linear", kTable, "techniques/linear.comp");
}

}  // namespace ssr
