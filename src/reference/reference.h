// `reference`: the ray-traced ground truth (ARCHITECTURE §5), a technique like the others.
//
// From the frame's own G-buffer (positions reconstructed from depth, read back), each reflective
// pixel's reflection rays are traced against the scene's triangles with Embree: one mirror ray,
// or `reference.samples` GGX VNDF samples (fixed seed) for rough pixels. The GPU shades the hits
// with the lit pass's shade_surface seen from the ray (no second copy of the shading code).
// Besides the truth it produces the per-pixel class (traceable / missing / sky) and the
// screen-space ideal: the lit colour at the true hit's pixel, the best any screen-space tracer
// could return.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "reference/pixel_class.h"
#include "techniques/technique.h"

namespace ssr {

class EmbreeScene;

class ReferenceTechnique;
std::unique_ptr<Technique> make_reference_technique();

// The extra outputs of the last run of a reference technique (nullptr for other techniques).
struct ReferenceOutputs {
  const gl::Texture2D* ideal = nullptr;     // RGBA16F screen-space ideal reflection
  const gl::Texture2D* ideal_refraction = nullptr;  // RGBA16F ideal refraction (glass pixels)
  const std::vector<PixelClass>* classes = nullptr;  // row 0 = top, as read-back images
  std::size_t rays = 0;                     // rays traced in the last run
};
ReferenceOutputs reference_outputs(const Technique& t);

// While a reference technique traces, `progress` is called on the calling (GL) thread about 20
// times a second with the share of rows taken so far (0..1): the viewer draws its progress bar
// from it. Does nothing for other techniques; an empty function turns it off.
void set_reference_progress(Technique& t, std::function<void(double)> progress);

}  // namespace ssr
