#include "tracer_test_util.h"

#include "gl_test_env.h"

#include <map>
#include <memory>
#include <tuple>

#include "core/cli_common.h"
#include "eval/runner.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace ssr::test {

namespace {
struct Cached {
  Scene scene;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Technique> reference;
  std::unique_ptr<ScoredFrame> frame;
  Camera camera;
};
std::map<std::tuple<std::string, std::string, int, int>, std::unique_ptr<Cached>>& cache() {
  static std::map<std::tuple<std::string, std::string, int, int>, std::unique_ptr<Cached>> c;
  return c;
}
}  // namespace

TracerScore score_technique(const std::string& scene, int w, int h, const std::string& technique,
                            const std::vector<std::string>& assignments, const std::string& camera) {
  auto& slot = cache()[{scene, camera, w, h}];
  if (!slot) {
    slot = std::make_unique<Cached>();
    slot->scene = load_scene(scene);
    slot->camera = camera.empty() ? slot->scene.cameras.front() : slot->scene.camera(camera);
    slot->renderer = std::make_unique<Renderer>(slot->scene, w, h);
    slot->reference = create_technique("reference");
    apply_assignments(*slot->reference, {"reference.samples=64"});
    slot->reference->load(slot->renderer->shaders());
    slot->frame = std::make_unique<ScoredFrame>(*slot->renderer, slot->camera, *slot->reference);
  }
  auto t = create_technique(technique);
  apply_assignments(*t, assignments);
  t->load(slot->renderer->shaders());
  TracerScore s;
  ScoredFrame::Score score = slot->frame->score(*t);
  std::string name = scene + "-" + std::to_string(w) + "x" + std::to_string(h) + "-" + technique;
  for (const std::string& a : assignments) name += "-" + a.substr(a.find('.') + 1);
  note_images_for_failure(name, score.display, slot->frame->truth());  // written if the test fails
  s.error = score.error;
  s.breakdown = std::move(score.breakdown);
  return s;
}

void clear_scored_frames() { cache().clear(); }

TechniqueOutputs render_outputs(Renderer& r, const std::string& technique, const std::vector<std::string>& assignments,
                                const gl::ShaderSource& shaders, bool debug) {
  auto t = create_technique(technique);
  apply_assignments(*t, assignments);
  t->load(shaders);
  r.debug_outputs = debug;
  for (int f = 1; f <= 2; ++f)
    r.render(FrameRequest(r.scene().cameras[0], FrameTime{f, 0.0f}), *t, ViewMode::Final, nullptr);
  return {r.read_texture(r.reflection()), r.read_texture(r.refraction()), r.read_texture(r.debug()),
          r.read_texture(r.color())};
}

void expect_same_outputs(const TechniqueOutputs& a, const TechniqueOutputs& b, const std::string& name, bool debug) {
  expect_same_image(a.reflection, b.reflection, name + "-reflection");
  expect_same_image(a.refraction, b.refraction, name + "-refraction");
  expect_same_image(a.color, b.color, name + "-color");
  if (debug) expect_same_image(a.debug, b.debug, name + "-debug");
}

}  // namespace ssr::test
