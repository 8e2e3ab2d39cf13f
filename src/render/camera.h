// Camera matrices: right-handed view (looking down -Z), reversed-Z projection (near -> 1, far -> 0,
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)).
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ssr {

glm::mat4 view_matrix(const Camera& c);
glm::mat4 reversed_z_projection(float fov_y_rad, float aspect, float near_plane, float far_plane);

struct CameraMatrices {
  glm::mat4 view, proj;
};
CameraMatrices camera_matrices(const Camera& c, int width, int height);

// Projects a world point to pixel coordinates (x right, y DOWN from the top row, as in a PNG),
// and the reversed-Z depth. Returns false behind the camera.
bool project_to_pixel(const CameraMatrices& m, int width, int height, const glm::vec3& world,
                      glm::vec2& pixel, float& depth);

}  // namespace ssr
