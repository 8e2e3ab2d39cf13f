// `dda`: McGuire & Mara 2014 (JCGT 3(4), "Efficient GPU Screen-Space Ray Tracing"). The view-space
// ray is clipped to the near plane and max_distance, projected once, and marched over the
// screen one pixel (times `stride`) along its major axis per step, interpolating 1/w and
// view/w linearly in screen space for perspective-correct depth. Each step compares the ray's
// z-range over the step with the depth buffer (thickness, or the shared back-face option);
// with stride > 1, bisection inside the last stride places the hit at pixel precision.
#include "shared/dda.h"
#include "techniques/tracer.h"

namespace ssr {
namespace {

using P = shared::DdaParams;
const std::vector<ParamDesc> kTable = with_ray_options<P>({
    SSR_PARAM_INT(P, max_steps, 1, 8192, "steps", "Screen-space steps before the ray gives up."),
    SSR_PARAM_FLOAT(P, stride, 1.0, 64.0, 1.0, "pixels", "Pixels along the ray's major axis per step."),
    SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                    "A ray this far or less behind the depth buffer counts as inside the surface."),
    SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 0.5, "world units", "Longest reflection ray, before near-plane clipping."),
    SSR_PARAM_INT(P, refine_steps, 0, 16, "steps", "Bisection steps inside the last stride when stride > 1 (0: keep the stride's hit)."),
    SSR_PARAM_BOOL(P, jitter, "Offset each ray's start by a per-pixel random fraction of the stride."),
});

}  // namespace

std::unique_ptr<Technique> make_dda_technique() {
  return std::make_unique<TracerTechnique<P>>("dda", kTable, "techniques/dda.comp");
}

}  // namespace ssr
