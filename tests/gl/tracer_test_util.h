// Scoring tracers against the reference in GL tests: one ScoredFrame per (scene, camera, size),
// cached for the whole test binary (the reference is the slow part) and freed before the GL
// context goes (gl_test_main.cpp calls clear_scored_frames()).
#pragma once
#include <string>
#include <vector>

#include "eval/breakdown.h"
#include "eval/metrics.h"
#include "gl/program.h"
#include "core/image.h"

namespace ssr {
class Renderer;
}

namespace ssr::test {

struct TracerScore {
  ErrorMetrics error;      // vs the reference (and the screen-space ideal on traceable pixels)
  Breakdown breakdown;     // per region and class
  double technique_ms = 0; // not used for asserts: timings never are
};

// Runs `technique` with `assignments` ("technique.key=value") on the scene's camera (default:
// its first) at w x h and scores it. The reference uses 64 samples for rough pixels.
TracerScore score_technique(const std::string& scene, int w, int h, const std::string& technique,
                            const std::vector<std::string>& assignments, const std::string& camera = "");

void clear_scored_frames();

// Every image a technique writes, for comparing two ways of running it.
struct TechniqueOutputs {
  RgbaImageF reflection, refraction, debug, color;
};

// Two frames of `technique` with `assignments`, loaded from `shaders` (the second frame's
// denoiser has history); the debug image written when `debug` (its own program variant).
TechniqueOutputs render_outputs(Renderer& r, const std::string& technique, const std::vector<std::string>& assignments,
                                const gl::ShaderSource& shaders, bool debug = true);

// expect_same_image on each image (the debug image only when `debug`); `name` prefixes the
// names of the images saved on a mismatch.
void expect_same_outputs(const TechniqueOutputs& a, const TechniqueOutputs& b, const std::string& name, bool debug);

}  // namespace ssr::test
