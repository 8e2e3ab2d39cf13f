#include "viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace ssr {

void CameraController::set(const Camera& c) {
  cam_ = c;
  from_camera();
}

// Spherical coordinates of the position around the target.
void CameraController::from_camera() {
  const glm::vec3 d = cam_.position - cam_.target;
  distance_ = std::max(glm::length(d), 1e-3f);
  yaw_ = std::atan2(d.x, d.z);
  pitch_ = std::asin(std::clamp(d.y / distance_, -1.0f, 1.0f));
}

void CameraController::place() {
  pitch_ = std::clamp(pitch_, -1.55f, 1.55f);
  cam_.position = cam_.target + distance_ * glm::vec3(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
                                                      std::cos(pitch_) * std::cos(yaw_));
  cam_.up = {0, 1, 0};
}

bool CameraController::update(const CameraInput& in) {
  const Camera before = cam_;
  const glm::vec3 fwd = glm::normalize(cam_.target - cam_.position);
  const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));
  if (in.fly != glm::vec3(0)) {
    const float step = kFlyPerSecond * in.speed * static_cast<float>(std::clamp(in.dt, 0.0, kMaxFlyStep));
    const glm::vec3 move = (right * in.fly.x + glm::vec3(0, in.fly.y, 0) + fwd * in.fly.z) * step;
    cam_.position += move;
    cam_.target += move;
  }
  if (in.orbit != glm::vec2(0)) {
    from_camera();
    yaw_ -= in.orbit.x * 0.005f;
    pitch_ += in.orbit.y * 0.005f;
    place();
  }
  if (in.pan != glm::vec2(0)) {
    const glm::vec3 up = glm::cross(right, fwd);
    const float k = glm::length(cam_.target - cam_.position) * 0.002f;
    const glm::vec3 pan = (-right * in.pan.x + up * in.pan.y) * k;
    cam_.position += pan;
    cam_.target += pan;
  }
  if (in.wheel != 0) {
    from_camera();
    distance_ = std::clamp(distance_ * std::pow(0.9f, in.wheel), 0.05f, 1000.0f);
    place();
  }
  return cam_.position != before.position || cam_.target != before.target;
}

}  // namespace ssr
