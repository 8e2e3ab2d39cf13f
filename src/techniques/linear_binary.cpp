// `linear-binary`: the Roberts paper. A view-space linear march of `linear_steps` samples up to
// `max_distance`; at the first sample inside a surface (behind it by less than the thickness),
// `binary_steps` of bisection between that sample and the previous one place the hit. Edge fade
// and the paper's blend (metallic^3 * -ray.z * fade) come with the shared tracer options.
#include "shared/linear_binary.h"
#include "techniques/tracer.h"

#include <algorithm>

namespace ssr {
namespace {

using P = shared::LinearBinaryParams;
const std::vector<ParamDesc> kTable = with_ray_options<P>(
    {
        SSR_PARAM_INT(P, linear_steps, 1, 8192, "steps", "Samples of the linear march between the origin and max_distance."),
        SSR_PARAM_INT(P, binary_steps, 0, 64, "steps", "Bisection steps that refine the first hit."),
        with_auto(SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                                  "A sample this far or less behind the depth buffer counts as inside the surface; "
                                  "auto: 1.5 linear steps (a step cannot pass through a surface unseen), at least 1% of the ray.")),
        with_auto(SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 0.5, "world units",
                                  "Length of the marched ray; auto: the scene's bounding-box diagonal.")),
    },
    /*with_blend=*/true);

// The paper's 9 m ray cannot reach gallery's back wall from its near floor, and a thickness
// below the step lets the march step over surfaces: both adapt unless set.
void resolve(P& p, const AutoContext& c) {
  if (p.max_distance == 0.0f) p.max_distance = c.max_distance();
  if (p.thickness == 0.0f)
    p.thickness = std::max(1.5f * p.max_distance / static_cast<float>(p.linear_steps), 0.01f * p.max_distance);
}

}  // namespace

std::unique_ptr<Technique> make_linear_binary_technique() {
  return std::make_unique<TracerTechnique<P>>("linear-binary", kTable, "techniques/linear_binary.comp", resolve);
}

}  // namespace ssr
