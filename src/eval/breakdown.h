// The verdict's breakdown (ARCHITECTURE §5): every figure per region (each planar reflector, all
// planar reflectors, other reflective surfaces, roughness bands) and per class (traceable /
// missing / sky), with hit classes, reflection-only error and the glossy noise floor.
//
// Inputs are display values (tone-mapped, in [0,1]) read back with row 0 at the top. An empty
// set has no figure (std::nullopt, `null` in JSON), never 100 dB.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/image.h"
#include "eval/metrics.h"
#include "shared/roughness_bands.h"

namespace ssr {

// Roughness bands (mirror < 0.05 <= glossy <= 0.4 < rough: MIRROR_BAND_BELOW, ROUGH_BAND_ABOVE),
// compared on the roughness as the G-buffer holds it (shared/roughness_bands.h).
using shared::as_stored_roughness;

// A technique "claims a hit" where its confidence exceeds this (as `coverage` does).
constexpr float kHitConfidence = 0.5f;
// A claimed hit on a traceable pixel is correct when its reflected radiance (before the
// specular weight, display values) is within this of the screen-space ideal's in every RGB
// channel: about 25/255, above bilinear-versus-nearest differences on textured surfaces, far
// below the difference between two surfaces of the test scenes.
constexpr float kCorrectHitTolerance = 0.1f;

// What the frame says about each pixel, row 0 = top.
struct PixelLabels {
  int width = 0, height = 0;
  std::vector<PixelClass> classes;       // the reference's class (NotReflective: no figure)
  std::vector<std::uint16_t> reflector;  // 0 = not on a planar reflector, else 1-based id
  std::vector<float> roughness;          // perceptual roughness as the G-buffer holds it (half float)
  // Pixels seen through a transparent surface (empty: none). Their class and figures are their
  // refraction's: they belong to "all" and "refractive" only.
  std::vector<bool> glass;
  int reflectors = 0;                    // planar reflectors in the scene
  bool is_glass(std::size_t i) const { return !glass.empty() && glass[i]; }
};

enum class RegionKind { All, Planar, Reflector, Other, Mirror, Glossy, Rough, Refractive };

struct Region {
  RegionKind kind = RegionKind::All;
  int reflector = 0;  // 1-based, for RegionKind::Reflector
  // "all", "planar", "reflector:N", "other", "mirror", "glossy", "rough", "refractive"
  std::string name() const;
  bool contains(const PixelLabels& l, std::size_t i) const;
};

// Every region of a frame in report order: all, planar, reflector:1..N, other, mirror, glossy,
// rough, refractive (reflector:N only for the scene's reflectors).
std::vector<Region> frame_regions(const PixelLabels& labels);
// Parses a region name as `--region`-style options take it; throws InputError on an unknown one.
Region parse_region(const std::string& name, int reflectors);
// Every name parse_region takes, in report order: "all,planar,reflector:N,other,...".
std::string region_names();

// Per-pixel verdict on a technique's claim.
enum class HitClass : std::uint8_t {
  NotReflective = 0,
  Correct = 1,      // claimed, right colour: on a traceable pixel the screen-space ideal's; on
                    // a missing or sky pixel the truth's (a technique that is not limited to
                    // the screen, as the planar oracle, gets them right)
  False = 2,        // claimed, wrong colour: the wrong surface on a traceable pixel; on a
                    // missing or sky pixel a guess (through the thickness, a hidden layer, hole
                    // filling) that is not what the truth reflects
  Missed = 3,       // traceable but not claimed
  CorrectMiss = 4,  // missing or sky, not claimed (the environment is the right fallback)
  NotHandled = 5,   // outside the technique's domain (non-planar pixels for ppr and planar)
};
// `expected`: the ideal's reflected colour on a traceable pixel, the truth's elsewhere.
HitClass classify_hit(PixelClass c, float confidence, const float* reflected, const float* expected);

// One technique's images on the frame; all display values, the same size as the labels.
struct TechniqueImages {
  const RgbaImageF* final = nullptr;      // composited image
  // Reflected radiance before the specular weight (on glass pixels: the refracted radiance
  // before the tint and Fresnel weight)
  const RgbaImageF* reflected = nullptr;
  const std::vector<float>* confidence = nullptr;
};

// The frame's references, display values.
struct ReferenceImages {
  const RgbaImageF* truth = nullptr;            // composited truth
  const RgbaImageF* ideal = nullptr;            // composited screen-space ideal
  const RgbaImageF* truth_reflected = nullptr;  // the truth's reflected radiance
  const RgbaImageF* ideal_reflected = nullptr;  // the ideal's reflected radiance
  // Composited ideal traced with the technique's own sample count (the noise floor), or null.
  const RgbaImageF* ideal_at_samples = nullptr;
};

struct ClassFigures {
  std::size_t pixels = 0;
  std::optional<double> psnr;                   // final image vs truth
  std::optional<double> psnr_ideal;             // final image vs screen-space ideal (traceable)
  std::optional<double> psnr_reflection;        // reflected radiance vs the truth's
  std::optional<double> psnr_reflection_ideal;  // reflected radiance vs the ideal's (traceable)
  std::optional<double> coverage;               // traceable: claimed share
  std::optional<double> correct_coverage;       // traceable: claimed with the right colour
  std::size_t correct_pixels = 0;               // traceable: the count behind correct_coverage
  std::optional<double> false_hit_rate;         // missing / sky: claimed share
  // Traceable: the ideal at the technique's sample count vs the converged ideal, over the
  // class's pixels that are not mirrors (null when none is, or no sample count is known).
  std::optional<double> noise_floor_psnr;
};

struct HitCounts {
  std::size_t correct = 0, false_hits = 0, missed = 0, correct_miss = 0;
};

struct RegionFigures {
  Region region;
  std::size_t pixels = 0;          // reflective pixels of the region
  bool handled = true;             // the technique handles every pixel of the region
  std::size_t handled_pixels = 0;  // those it handles; the figures below cover only these
  ClassFigures traceable, missing, sky;
  HitCounts hits;
};

struct Breakdown {
  std::vector<RegionFigures> regions;  // frame_regions() order
  const RegionFigures* find(const std::string& name) const;  // nullptr when absent
};

// `planar_only`: the technique handles planar reflector pixels only (ppr, planar).
Breakdown compute_breakdown(const PixelLabels& labels, const TechniqueImages& technique,
                            const ReferenceImages& refs, bool planar_only);

// The per-pixel hit classes of a technique (row 0 = top).
std::vector<HitClass> hit_classes(const PixelLabels& labels, const TechniqueImages& technique,
                                  const ReferenceImages& refs, bool planar_only);

// The inherent error of screen space: ideal vs truth per class, over all reflective pixels.
struct InherentFigures {
  std::optional<double> traceable, missing, sky;
};
InherentFigures compute_inherent(const PixelLabels& labels, const ReferenceImages& refs);

// `planar` vs `reference` on mirror (roughness below `max_roughness`) planar reflector pixels
// that `eligible` admits (e.g. not normal-mapped): the PSNR of their reflected radiance and the
// share of pixels whose every channel is within 1/255, which a few silhouette pixels cannot sink.
struct OracleAgreement {
  std::size_t pixels = 0;
  std::optional<double> psnr, within_1_255;
  // The PSNR off edges: without the pixels whose 3x3 neighbourhood in the truth spans more than
  // kOracleEdgeContrast in some channel (reflected silhouettes and sharp edges, where a raster
  // and a ray tracer legitimately disagree on which surface a pixel centre sees).
  std::size_t edge_pixels = 0;
  std::optional<double> psnr_off_edges;
};
constexpr float kOracleEdgeContrast = 0.1f;
OracleAgreement compare_oracles(const PixelLabels& labels, const RgbaImageF& planar_reflected,
                                const RgbaImageF& truth_reflected, const std::vector<bool>& eligible,
                                float max_roughness = 0.01f);

}  // namespace ssr
