// `hiz`: hierarchical-Z tracing (Uludag, GPU Pro 5; Kim 2018, 2.3.2). It declares the depth
// pyramid, which the frame builds before the trace: an R32F pyramid of the depth buffer keeping the max of each
// footprint: with reversed-Z that is the closest depth, a bound no surface in the cell is in
// front of. The trace (shaders/techniques/hiz.comp) skips whole cells the ray stays in front
// of and descends where it may pass behind one, up to `max_iterations` cell visits.
#include <algorithm>
#include <cmath>

#include "shared/hiz.h"
#include "techniques/tracer.h"

namespace ssr {

namespace {

using P = shared::HizParams;
const std::vector<ParamDesc> kTable = with_ray_options<P>({
    with_auto(SSR_PARAM_INT(P, max_iterations, 1, 4096, "iterations",
                            "Cap on pyramid cell visits per ray; a ray still marching at the cap is a miss; "
                            "auto: half the image diagonal in pixels.")),
    SSR_PARAM_INT(P, start_level, 0, 8, "level", "Pyramid level of the first step after leaving the origin pixel."),
    SSR_PARAM_INT(P, max_level, 0, 15, "level", "Coarsest pyramid level the trace climbs to (capped by the chain)."),
    SSR_PARAM_FLOAT(P, thickness, 0.001, 50.0, 0.01, "world units",
                    "A ray point this far or less behind the depth buffer counts as a hit."),
    with_auto(SSR_PARAM_FLOAT(P, max_distance, 0.01, 10000.0, 0.5, "world units",
                              "Length of the traced ray; auto: the scene's bounding-box diagonal.")),
});

// The visits a ray needs grow with the resolution: 256 reached 98% of pedestal's wall mirror at
// 640x360 but 47% at 1920x1080 (1024: 99.8%).
void resolve(P& p, const AutoContext& c) {
  if (p.max_distance == 0.0f) p.max_distance = c.max_distance();
  if (p.max_iterations == 0) p.max_iterations = c.hiz_iterations();
}

class HizTechnique : public TracerTechnique<P> {
 public:
  HizTechnique() : TracerTechnique<P>("hiz", kTable, "techniques/hiz.comp", resolve) {
    extra_reads_ = kReadHiz;  // the frame builds the pyramid (render/hiz_pyramid.h)
  }
};

}  // namespace

std::unique_ptr<Technique> make_hiz_technique() { return std::make_unique<HizTechnique>(); }

}  // namespace ssr
