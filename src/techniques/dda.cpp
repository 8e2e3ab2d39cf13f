// `dda`: McGuire & Mara 2014 (JCGT 3(4), "Efficient GPU Screen-Space Ray Tracing"). The view-space
// ray is clipped to the near plane and max_distance, projected once, and marched over the
// screen one pixel (times `stride`) along its major axis per step, interpolating 1/w and
// view/w linearly in screen space for perspective-correct depth.
// Choices (shaders/techniques/dda.comp says why):
// - hit test: the paper's z-range test (the step's view-z interval against the depth buffer),
//   phrased through inside_surface() so the shared back-face thickness option works;
// - with stride > 1, bisection inside the stride places the hit at pixel precision;
// - no self-hits: a hit needs an earlier step wholly in front of the visible surface, or a
//   surface in front of the origin's tangent plane (contact reflections, e.g. wall on floor);
// - jitter shifts the grid of steps instead of skipping the ray's first jitter * stride pixels.
#include "shared/dda.h"
#include "techniques/tracer.h"

#include <algorithm>
#include <cmath>

namespace ssr {
namespace {

using P = shared::DdaParams;
const std::vector<ParamDesc> kTable = with_ray_options<P>({
    with_auto(SSR_PARAM_INT(P, max_steps, 1, 8192, "steps",
                            "Screen-space steps before the ray gives up; auto: the image diagonal over the stride, "
                            "so that a ray can cross the screen at any resolution.")),
    SSR_PARAM_FLOAT(P, stride, 1.0, 64.0, 1.0, "pixels", "Pixels along the ray's major axis per step."),
    SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                    "A ray this far or less behind the depth buffer counts as inside the surface."),
    with_auto(SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 0.5, "world units",
                              "Longest reflection ray, before near-plane clipping; auto: the scene's bounding-box diagonal.")),
    SSR_PARAM_INT(P, refine_steps, 0, 16, "steps", "Bisection steps inside the last stride when stride > 1 (0: keep the stride's hit)."),
    SSR_PARAM_BOOL(P, jitter, "Shift each pixel's steps by a random fraction of the stride: banding from large strides becomes noise."),
});

// A fixed step count covers a fixed number of pixels (256 steps of 1 px reached 37% of
// gallery's floor at 1080p, 19% at 4K): the auto count covers the image diagonal.
void resolve(P& p, const AutoContext& c) {
  if (p.max_steps == 0) p.max_steps = std::clamp(static_cast<int>(std::ceil(c.image_diagonal / p.stride)), 1, 8192);
  if (p.max_distance == 0.0f) p.max_distance = c.max_distance();
}

}  // namespace

std::unique_ptr<Technique> make_dda_technique() {
  return std::make_unique<TracerTechnique<P>>("dda", kTable, "techniques/dda.comp", resolve);
}

}  // namespace ssr
