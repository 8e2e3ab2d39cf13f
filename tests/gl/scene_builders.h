// Small helpers for the GL tests' hand-built scenes.
#pragma once
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "scene/meshgen.h"
#include "scene/scene.h"

namespace ssr::test {

inline Material material(glm::vec3 albedo, float roughness, float metallic, float reflectance) {
  Material m;
  m.name = "m";
  m.albedo = albedo;
  m.roughness = roughness;
  m.metallic = metallic;
  m.reflectance = reflectance;
  return m;
}

inline void add_mesh(Scene& s, Mesh m, const std::string& name, int mat, const glm::mat4& xf, int reflector = 0) {
  meshgen::transform(m, xf);
  m.name = name;
  m.material = mat;
  m.reflector = reflector;
  s.meshes.push_back(std::move(m));
}

inline Light point_light(glm::vec3 position, float intensity) {
  Light l;
  l.position = position;
  l.intensity = intensity;
  l.range = 30.0f;
  return l;
}

inline Camera camera(const char* name, glm::vec3 position, glm::vec3 target, float fov_y_deg) {
  Camera c;
  c.name = name;
  c.position = position;
  c.target = target;
  c.fov_y_deg = fov_y_deg;
  return c;
}

}  // namespace ssr::test
