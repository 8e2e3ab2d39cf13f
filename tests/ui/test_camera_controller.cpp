// The viewer's camera controller without a window: flight per frame does not grow with the
// frame's duration past 1/30 s (a slow frame must not throw the camera across the scene), orbit
// keeps the distance to the target, the wheel zooms towards it, panning moves both ends.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "viewer/camera_controller.h"

namespace ssr {
namespace {

Camera start() {
  Camera c;
  c.name = "test";
  c.position = {0, 1, 5};
  c.target = {0, 1, 0};
  c.up = {0, 1, 0};
  return c;
}

float flown(double dt) {
  CameraController k;
  k.set(start());
  CameraInput in;
  in.fly = {0, 0, 1};
  in.dt = dt;
  EXPECT_TRUE(k.update(in));
  return glm::length(k.camera().position - start().position);
}

TEST(CameraController, FlightPerFrameIsCappedOnSlowFrames) {
  const float fast = flown(1.0 / 60.0), capped = flown(1.0 / 30.0), slow = flown(2.0);
  EXPECT_NEAR(fast, CameraController::kFlyPerSecond / 60.0f, 1e-5f);
  EXPECT_NEAR(capped, CameraController::kFlyPerSecond / 30.0f, 1e-5f);
  EXPECT_FLOAT_EQ(slow, capped);  // a 2 s frame flies as far as a 1/30 s one
}

TEST(CameraController, FlyMovesTargetWithPositionAndSpeedScales) {
  CameraController k;
  k.set(start());
  CameraInput in;
  in.fly = {1, 0, 0};
  in.dt = 1.0 / 30.0;
  in.speed = 4.0f;
  k.update(in);
  EXPECT_NEAR(k.camera().position.x, 4.0f * CameraController::kFlyPerSecond / 30.0f, 1e-5f);
  EXPECT_NEAR(glm::length(k.camera().target - k.camera().position), 5.0f, 1e-4f);
}

TEST(CameraController, OrbitKeepsDistanceWheelZoomsPanMovesBoth) {
  CameraController k;
  k.set(start());
  CameraInput orbit;
  orbit.orbit = {120, -40};
  EXPECT_TRUE(k.update(orbit));
  EXPECT_NEAR(glm::length(k.camera().position - k.camera().target), 5.0f, 1e-4f);
  EXPECT_GT(glm::length(k.camera().position - start().position), 0.1f);
  CameraInput wheel;
  wheel.wheel = 1;
  k.update(wheel);
  EXPECT_NEAR(glm::length(k.camera().position - k.camera().target), 4.5f, 1e-4f);
  const glm::vec3 target = k.camera().target;
  CameraInput pan;
  pan.pan = {30, 0};
  k.update(pan);
  EXPECT_GT(glm::length(k.camera().target - target), 0.01f);
  EXPECT_NEAR(glm::length(k.camera().position - k.camera().target), 4.5f, 1e-4f);
  EXPECT_FALSE(k.update(CameraInput{}));  // no input, no motion
}

}  // namespace
}  // namespace ssr
