#include "render/camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace ssr {

glm::mat4 view_matrix(const Camera& c) { return glm::lookAtRH(c.position, c.target, c.up); }

glm::mat4 reversed_z_projection(float fov_y_rad, float aspect, float n, float f) {
  const float t = 1.0f / std::tan(fov_y_rad * 0.5f);
  glm::mat4 p(0.0f);
  p[0][0] = t / aspect;
  p[1][1] = t;
  p[2][2] = n / (f - n);       // z_clip = A z + B, w_clip = -z: depth = B / -z - A
  p[3][2] = n * f / (f - n);
  p[2][3] = -1.0f;
  return p;
}

CameraMatrices camera_matrices(const Camera& c, int width, int height) {
  return {view_matrix(c), reversed_z_projection(glm::radians(c.fov_y_deg),
                                                float(width) / float(height), c.near_plane,
                                                c.far_plane)};
}

bool project_to_pixel(const CameraMatrices& m, int width, int height, const glm::vec3& world,
                      glm::vec2& pixel, float& depth) {
  const glm::vec4 clip = m.proj * m.view * glm::vec4(world, 1.0f);
  if (clip.w <= 1e-6f) return false;
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  pixel = {(ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height)};
  depth = ndc.z;
  return true;
}

}  // namespace ssr
