// The viewer's camera: orbit around the target (left drag), pan (right drag), zoom (wheel),
// fly (WASD/QE). Window-free, so the ui tests drive it with made-up input.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace ssr {

// What the input asked for during one frame.
struct CameraInput {
  glm::vec2 orbit{0};   // pixels dragged with the left button
  glm::vec2 pan{0};     // pixels dragged with the right button
  float wheel = 0;      // wheel notches
  glm::vec3 fly{0};     // +x right, +y up, +z forward; each -1, 0 or 1
  float speed = 1;      // fly multiplier (Shift x4, Ctrl x0.25)
  double dt = 0;        // seconds since the last frame
};

class CameraController {
 public:
  // Metres a frame flies at speed 1, whatever the frame took: a slow frame (a CPU reference,
  // llvmpipe) must not throw the camera across the scene.
  static constexpr float kFlyPerSecond = 3.0f;
  static constexpr double kMaxFlyStep = 1.0 / 30.0;  // seconds of flight a frame at most

  void set(const Camera& c);
  const Camera& camera() const { return cam_; }
  Camera& camera() { return cam_; }
  // Applies one frame of input; returns true when the camera moved.
  bool update(const CameraInput& in);

 private:
  void from_camera();
  void place();
  Camera cam_;
  float yaw_ = 0, pitch_ = 0, distance_ = 1;
};

}  // namespace ssr
