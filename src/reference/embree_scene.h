// The scene's triangles in an Embree 3 BVH, for the ray-traced ground truth.
#pragma once
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ssr {

struct RayHit {
  bool hit = false;
  float t = 0;
  int mesh = -1;            // index into Scene::meshes
  glm::vec3 position{0};    // world
  glm::vec3 normal{0};      // unit shading normal (interpolated), turned to face the ray
  glm::vec2 uv{0};
  glm::vec4 tangent{0};     // xyz interpolated tangent along +u (not normalised), w handedness
  float cos_incidence = 1;  // |dot(geometric normal, ray direction)|
  float uv_density = 0;     // uv units per world unit on the hit triangle (texture LOD)
};

class EmbreeScene {
 public:
  // Opaque meshes only (transparent ones are left out, as in the G-buffer). Throws RuntimeError
  // when Embree fails.
  explicit EmbreeScene(const Scene& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Closest hit along origin + t * dir for t in (t_near, inf). Thread-safe.
  RayHit trace(const glm::vec3& origin, const glm::vec3& dir, float t_near = 0.0f) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ssr
