// `hiz`: hierarchical-Z tracing (Uludag, GPU Pro 5; Kim 2018, 2.3.2). Before the trace, a
// compute pass per level builds an R32F pyramid of the depth buffer keeping the max of each
// footprint: with reversed-Z that is the closest depth, a bound no surface in the cell is in
// front of. The trace (shaders/techniques/hiz.comp) skips whole cells the ray stays in front
// of and descends where it may pass behind one, up to `max_iterations` cell visits.
#include "techniques/hiz_pyramid.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "shared/hiz.h"
#include "techniques/tracer.h"

namespace ssr {

std::vector<std::pair<int, int>> hiz_level_sizes(int w, int h) {
  std::vector<std::pair<int, int>> sizes{{w, h}};
  while (w > 1 || h > 1) {
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    sizes.emplace_back(w, h);
  }
  return sizes;
}

void HizPyramid::load(const gl::ShaderSource& src) {
  program_ = gl::Program::compute(src, "techniques/hiz_pyramid.comp");
}

void HizPyramid::build(const gl::Texture2D& depth) {
  const int w = depth.width(), h = depth.height();
  if (!texture_ || texture_.width() != w || texture_.height() != h)
    texture_ = gl::Texture2D("hiz depth pyramid", GL_R32F, w, h, /*levels=*/0);  // full chain
  const auto sizes = hiz_level_sizes(w, h);
  // GL's mip chain is the same chain: floor halving down to 1x1.
  assert(static_cast<int>(sizes.size()) == texture_.levels());
  glBindTextureUnit(TEX_HIZ, depth.id());
  for (int level = 0; level < texture_.levels(); ++level) {
    if (level == 1) glBindTextureUnit(TEX_HIZ, texture_.id());  // from now on, read the level below
    glProgramUniform1i(program_.id(), 0, level - 1);              // -1: copy the depth buffer
    glBindImageTexture(IMG_OUT, texture_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    const auto [lw, lh] = sizes[static_cast<std::size_t>(level)];
    program_.dispatch_2d(lw, lh);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the next level (and the trace) fetch this one
  }
  glBindTextureUnit(TEX_HIZ, texture_.id());  // for the trace (a 1x1 chain never rebound it)
}

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
  if (p.max_distance == 0.0f) p.max_distance = std::max(c.scene_diagonal, 0.01f);
  if (p.max_iterations == 0) p.max_iterations = std::clamp(static_cast<int>(std::ceil(0.5f * c.image_diagonal)), 1, 4096);
}

class HizTechnique : public TracerTechnique<P> {
 public:
  HizTechnique() : TracerTechnique<P>("hiz", kTable, "techniques/hiz.comp", resolve) {}
  void load(const gl::ShaderSource& src) override {
    pyramid_.load(src);
    TracerTechnique<P>::load(src);
  }

 protected:
  void prepare(const TechniqueInputs& in) override { pyramid_.build(in.gbuffer.depth); }

 private:
  HizPyramid pyramid_;
};

}  // namespace

std::unique_ptr<Technique> make_hiz_technique() { return std::make_unique<HizTechnique>(); }

}  // namespace ssr
