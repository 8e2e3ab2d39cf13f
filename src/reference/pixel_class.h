// The ground truth's class of each reflective pixel: the reference computes it, the metrics
// split every figure by it (ARCHITECTURE §5).
#pragma once
#include <cstdint>

namespace ssr {

// What the ground truth says about one pixel's reflection (per pixel, majority of its samples).
enum class PixelClass : std::uint8_t {
  NotReflective = 0,  // no reflection work here (excluded from every metric)
  Traceable = 1,      // the true hit is on screen and visible in the depth buffer
  Missing = 2,        // the true hit is off screen or hidden: no screen-space method can get it
  Sky = 3,            // the true ray escapes to the environment (confidence 0 is the right answer)
};

}  // namespace ssr
