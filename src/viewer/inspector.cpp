#include "viewer/inspector.h"

#include <array>
#include <cmath>

#include "gl/gl.h"
#include "gl/readback.h"
#include "shared/bindings.h"
#include "shared/tonemap.h"

namespace ssr {

namespace {

PixelValues vec(const float* v, int n) {
  PixelValues a = PixelValues::array();
  for (int i = 0; i < n; ++i) a.push_back(std::isfinite(v[i]) ? PixelValues(v[i]) : PixelValues(nullptr));
  return a;
}

}  // namespace

const char* side_key(int i) { return i == 0 ? "a" : i == 1 ? "b" : "truth"; }

const char* pixel_class_name(PixelClass c) {
  switch (c) {
    case PixelClass::NotReflective: return "not-reflective";
    case PixelClass::Traceable: return "traceable";
    case PixelClass::Missing: return "missing";
    case PixelClass::Sky: return "sky";
  }
  return "?";
}

PixelValues inspect_pixel(const Renderer& r, int x, int y, const SideImages* sides, int n_sides,
                             const std::vector<PixelClass>* classes, std::optional<int> truth) {
  const GBuffer& g = r.gbuffer();
  PixelValues j;
  j["pixel"] = {x, y};
  const float depth = gl::read_texel<float, 1>(g.depth, x, y, GL_DEPTH_COMPONENT, GL_FLOAT)[0];
  j["depth"] = depth;
  // View-space position from the pixel and the reversed-Z depth (the inverse projection).
  const float w = static_cast<float>(g.depth.width()), h = static_cast<float>(g.depth.height());
  const glm::vec4 ndc((x + 0.5f) / w * 2.0f - 1.0f, 1.0f - (y + 0.5f) / h * 2.0f, depth, 1.0f);
  const glm::vec4 view = glm::inverse(r.matrices().proj) * ndc;
  j["view_depth"] = depth > 0.0f ? PixelValues(-view.z / view.w) : PixelValues(nullptr);  // 0: the sky
  const auto nr = gl::read_texel<float, 4>(g.normal_roughness, x, y, GL_RGBA, GL_FLOAT);
  j["normal"] = vec(nr.data(), 3);
  j["roughness"] = nr[3];
  const auto am = gl::read_texel<std::uint8_t, 4>(g.albedo_metallic, x, y, GL_RGBA, GL_UNSIGNED_BYTE);
  j["albedo"] = {am[0] / 255.0, am[1] / 255.0, am[2] / 255.0};
  j["metallic"] = am[3] / 255.0;
  const auto m = gl::read_texel<std::uint16_t, 4>(g.material, x, y, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT);
  j["reflector"] = m[0];
  j["reflectance"] = m[1] / 255.0;
  j["flags"] = m[2];
  j["object"] = m[3];
  const auto e = gl::read_texel<float, 4>(g.emission, x, y, GL_RGBA, GL_FLOAT);
  j["emission"] = vec(e.data(), 3);
  const auto mv = gl::read_texel<float, 4>(r.motion(), x, y, GL_RGBA, GL_FLOAT);
  j["motion"] = vec(mv.data(), 2);  // pixels to last frame's position
  j["reflective"] = depth > 0.0f && (m[2] & MATERIAL_FLAG_REFLECTIVE) != 0u;
  const std::size_t at = static_cast<std::size_t>(y) * g.depth.width() + x;
  j["class"] = classes && at < classes->size() ? PixelValues(pixel_class_name((*classes)[at])) : PixelValues(nullptr);
  j["exposure"] = r.settings.exposure;
  std::array<std::array<std::uint8_t, 4>, 3> shown{};
  for (int i = 0; i < n_sides; ++i) {
    const SideImages& s = sides[i];
    PixelValues k;
    k["technique"] = s.technique;
    const auto c = gl::read_texel<float, 4>(*s.color, x, y, GL_RGBA, GL_FLOAT);
    k["colour"] = vec(c.data(), 3);
    shown[i] = gl::read_texel<std::uint8_t, 4>(*s.display, x, y, GL_RGBA, GL_UNSIGNED_BYTE);
    k["display"] = {shown[i][0], shown[i][1], shown[i][2]};
    if (s.debug) {
      const auto d = gl::read_texel<float, 4>(*s.debug, x, y, GL_RGBA, GL_FLOAT);
      if (s.ppr_offsets) k["offset"] = vec(d.data(), 2);
      else {
        k["steps"] = d[0];
        k["hits"] = d[1];
        k["hit_distance"] = d[2];
      }
    }
    j[side_key(i)] = k;
  }
  if (truth && *truth < n_sides) {
    // The error against the truth as the figures take it: display values of the final colour.
    const auto tc = gl::read_texel<float, 4>(*sides[*truth].color, x, y, GL_RGBA, GL_FLOAT);
    const glm::vec3 t = shared::display_transform(glm::vec3(tc[0], tc[1], tc[2]), r.settings.exposure);
    for (int i = 0; i < n_sides; ++i) {
      const auto c = gl::read_texel<float, 4>(*sides[i].color, x, y, GL_RGBA, GL_FLOAT);
      const glm::vec3 v = shared::display_transform(glm::vec3(c[0], c[1], c[2]), r.settings.exposure);
      const glm::vec3 d = glm::abs(v - t);
      j[side_key(i)]["error"] = (d.x + d.y + d.z) / 3.0f;
    }
  }
  return j;
}

}  // namespace ssr
