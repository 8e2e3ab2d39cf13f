// `planar`: the classic planar-mirror render, an oracle independent of the ray tracer.
// For each planar reflector, the scene is rendered again (G-buffer + lighting) from the camera
// mirrored across the reflector's plane, with everything behind the mirror clipped away; each
// pixel of that reflector then takes the colour its reflected ray sees in the mirrored image.
// Mirror only: roughness is ignored, pixels off the reflectors get confidence 0.
#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "render/renderer.h"
#include "techniques/technique.h"

namespace ssr {
namespace {

struct PlanarParams {};

class PlanarTechnique final : public TechniqueWithParams<PlanarParams> {
 public:
  PlanarTechnique() : TechniqueWithParams("planar", {}) {}

  void load(const gl::ShaderSource& src) override {
    shaders_ = src;
    resolve_ = gl::Program::compute(src, "reference/planar_resolve.comp");
    mirror_.reset();  // rebuilt with the new shaders on the next run
  }

  TechniqueDecl declare() const override {
    TechniqueDecl d;
    d.reads = kReadGBuffer | kReadReflectors;
    d.planar_only = true;
    return d;
  }

  void run(const FrameContext& in) override {
    const gl::Texture2D& reflection = *in.reflection;
    gl::ScopedPass pass(in.timer, "planar");
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(reflection.id(), 0, GL_RGBA, GL_FLOAT, zero);
    if (in.scene.reflectors.empty()) return;
    if (!mirror_ || mirror_geometry_ != in.geometry_id) {
      // The frame's scene as posed now; the mirror renderer must not animate it again.
      Scene still = in.scene;
      still.animation = {};
      mirror_.reset();
      mirror_ = std::make_unique<Renderer>(still, in.width, in.height, shaders_);
      mirror_geometry_ = in.geometry_id;
    }
    mirror_->resize(in.width, in.height);
    // The frame's lighting as it is now (the viewer edits it live; the mirror renderer caches
    // its inputs and would otherwise keep the lights it was built with).
    mirror_->set_lighting(in.scene.lights, in.scene.environment, in.scene.ambient);
    const Camera& cam = in.camera;
    for (std::size_t k = 0; k < in.scene.reflectors.size(); ++k) {
      const Reflector& r = in.scene.reflectors[k];
      glm::vec3 n = r.normal();
      const float side = glm::dot(n, cam.position - r.center);
      if (std::abs(side) < 1e-6f) continue;  // camera in the plane: the mirror covers no pixel
      if (side < 0) n = -n;                  // the mirror's front faces the camera
      auto mirror_point = [&](glm::vec3 p) { return p - 2.0f * glm::dot(p - r.center, n) * n; };
      Camera m = cam;
      m.position = mirror_point(cam.position);
      m.target = mirror_point(cam.target);
      m.up = cam.up - 2.0f * glm::dot(cam.up, n) * n;
      // Clip the mirror's own plane too (a hair in front of it), or the mirrored camera would
      // see the reflector from behind. The hair covers the float rounding of dot(plane, p) for
      // points around the reflector (a few ulps of its coordinates), not more: a thicker slab
      // would clip objects standing on the mirror.
      const glm::vec3 ac = glm::abs(r.center);
      const float eps = 1e-4f + 4e-7f * std::max({ac.x, ac.y, ac.z});
      mirror_->settings.clip_plane = glm::vec4(n, -glm::dot(n, r.center) - eps);
      mirror_->render_inputs(m, nullptr);

      in.rebind();  // back to this frame's G-buffer and uniforms
      const CameraMatrices mm = camera_matrices(m, in.width, in.height);
      const glm::mat4 vp = mm.proj * mm.view;
      glProgramUniformMatrix4fv(resolve_.id(), 0, 1, GL_FALSE, &vp[0][0]);
      glProgramUniform1ui(resolve_.id(), 1, static_cast<GLuint>(k + 1));
      glBindTextureUnit(TEX_PLANAR_MIRROR_LIT, mirror_->lit().id());
      glBindImageTexture(IMG_OUT, reflection.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
      resolve_.dispatch_2d(in.width, in.height);
      glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
  }

 private:
  gl::ShaderSource shaders_;
  gl::Program resolve_;
  std::unique_ptr<Renderer> mirror_;
  std::uint64_t mirror_geometry_ = 0;  // FrameContext::geometry_id of the frame being mirrored
};

}  // namespace

std::unique_ptr<Technique> make_planar_technique() { return std::make_unique<PlanarTechnique>(); }

}  // namespace ssr
