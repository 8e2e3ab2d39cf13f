// The breakdown's figures on synthetic frames with known answers: regions, classes, hit
// classes, reflection-only error, noise floor, not-handled regions and null for empty sets.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "eval/breakdown.h"
#include "eval/results.h"

using namespace ssr;

namespace {

// A 4x4 frame. Rows: 0 traceable, 1 missing, 2 sky, 3 not reflective. Columns: 0 and 1 on
// reflector 1 (mirror), 2 on reflector 2 (glossy 0.2), 3 off the reflectors (rough 0.7).
PixelLabels labels4() {
  PixelLabels l;
  l.width = l.height = 4;
  l.reflectors = 2;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      l.classes.push_back(static_cast<PixelClass>((y + 1) % 4));
      l.reflector.push_back(static_cast<std::uint16_t>(x < 2 ? 1 : x == 2 ? 2 : 0));
      l.roughness.push_back(x < 2 ? 0.0f : x == 2 ? 0.2f : 0.7f);
    }
  return l;
}

RgbaImageF filled(float v) { return RgbaImageF{4, 4, std::vector<float>(64, v)}; }

void set_px(RgbaImageF& im, int x, int y, float v) {
  for (int c = 0; c < 3; ++c) im.at(x, y)[c] = v;
}

struct Frame {
  PixelLabels labels = labels4();
  RgbaImageF truth = filled(0.5f), ideal = filled(0.5f), truth_r = filled(0.5f), ideal_r = filled(0.5f);
  RgbaImageF tech = filled(0.5f), tech_r = filled(0.5f);
  // Claims on the traceable row only: every answer right.
  std::vector<float> conf = {1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  ReferenceImages refs() { return {&truth, &ideal, &truth_r, &ideal_r, nullptr}; }
  TechniqueImages technique() { return {&tech, &tech_r, &conf}; }
};

}  // namespace

TEST(Breakdown, RegionsCoverTheirPixels) {
  const PixelLabels l = labels4();
  std::vector<std::string> names;
  for (const Region& r : frame_regions(l)) names.push_back(r.name());
  EXPECT_EQ(names, (std::vector<std::string>{"all", "planar", "reflector:1", "reflector:2", "other",
                                             "mirror", "glossy", "rough", "refractive"}));
  auto count = [&](const std::string& name) {
    const Region r = parse_region(name, l.reflectors);
    int n = 0;
    for (std::size_t i = 0; i < 16; ++i) n += r.contains(l, i);
    return n;
  };
  // 12 reflective pixels (3 rows x 4 columns).
  EXPECT_EQ(count("all"), 12);
  EXPECT_EQ(count("planar"), 9);
  EXPECT_EQ(count("reflector:1"), 6);
  EXPECT_EQ(count("reflector:2"), 3);
  EXPECT_EQ(count("other"), 3);
  EXPECT_EQ(count("mirror"), 6);
  EXPECT_EQ(count("glossy"), 3);
  EXPECT_EQ(count("rough"), 3);
  // The band edges, on roughness as the G-buffer's half float holds it (0.05 is 0.049988 there,
  // below a float 0.05): 0.05 is glossy, 0.4 is glossy, just above is rough, just below 0.05 mirror.
  PixelLabels e = l;
  e.roughness[0] = as_stored_roughness(0.05f);
  e.roughness[1] = as_stored_roughness(0.4f);
  e.roughness[2] = as_stored_roughness(0.4003f);
  e.roughness[3] = as_stored_roughness(0.0499f);
  EXPECT_LT(e.roughness[0], 0.05f);
  EXPECT_TRUE(parse_region("glossy", 2).contains(e, 0));
  EXPECT_TRUE(parse_region("glossy", 2).contains(e, 1));
  EXPECT_TRUE(parse_region("rough", 2).contains(e, 2));
  EXPECT_TRUE(parse_region("mirror", 2).contains(e, 3));
}

TEST(Breakdown, UnknownRegionsAreInputErrors) {
  EXPECT_THROW(parse_region("floor", 2), InputError);
  EXPECT_THROW(parse_region("reflector:3", 2), InputError);
  EXPECT_THROW(parse_region("reflector:0", 2), InputError);
  EXPECT_THROW(parse_region("reflector:", 2), InputError);
  EXPECT_THROW(parse_region("reflector:1x", 2), InputError);
  EXPECT_EQ(parse_region("reflector:2", 2).reflector, 2);
}

TEST(Breakdown, HitClassesFollowConfidenceClassAndColour) {
  const float a[3] = {0.5f, 0.5f, 0.5f};
  const float near[3] = {0.59f, 0.5f, 0.41f};  // within 0.1 in every channel
  const float far[3] = {0.5f, 0.62f, 0.5f};
  const float nan3[3] = {NAN, 0.5f, 0.5f};
  EXPECT_EQ(classify_hit(PixelClass::Traceable, 1.0f, a, near), HitClass::Correct);
  EXPECT_EQ(classify_hit(PixelClass::Traceable, 1.0f, a, far), HitClass::False);
  EXPECT_EQ(classify_hit(PixelClass::Traceable, 0.5f, a, a), HitClass::Missed);  // 0.5 is no claim
  // On missing and sky pixels a claim is judged against the truth's colour: a wrong guess is
  // false, the truth itself (a technique not limited to the screen) is correct.
  EXPECT_EQ(classify_hit(PixelClass::Missing, 0.51f, a, far), HitClass::False);
  EXPECT_EQ(classify_hit(PixelClass::Sky, 0.9f, a, far), HitClass::False);
  EXPECT_EQ(classify_hit(PixelClass::Missing, 0.9f, a, near), HitClass::Correct);
  EXPECT_EQ(classify_hit(PixelClass::Sky, 0.9f, nan3, a), HitClass::False);
  EXPECT_EQ(classify_hit(PixelClass::Sky, 0.0f, a, a), HitClass::CorrectMiss);
  EXPECT_EQ(classify_hit(PixelClass::NotReflective, 1.0f, a, a), HitClass::NotReflective);
  EXPECT_EQ(classify_hit(PixelClass::Traceable, 1.0f, nan3, a), HitClass::False);
  EXPECT_EQ(classify_hit(PixelClass::Traceable, NAN, a, a), HitClass::Missed);
}

TEST(Breakdown, KnownErrorsPerRegionAndClass) {
  Frame f;
  // Traceable reflector:1 pixels off by 0.1 from the ideal (the truth differs from the ideal by
  // 0.3 there): 20 dB vs ideal, 20*log10(1/0.2) vs truth. Reflected radiance off by 0.01: 40 dB.
  for (int x = 0; x < 2; ++x) {
    set_px(f.ideal, x, 0, 0.4f);
    set_px(f.truth, x, 0, 0.7f);
    set_px(f.tech, x, 0, 0.5f);
    set_px(f.tech_r, x, 0, 0.51f);
  }
  // Missing pixel (0,1) claimed with a wrong colour; sky pixel (3,2) claimed with the truth's
  // colour (not a false hit); traceable (2,0) not claimed.
  f.conf[4] = 0.9f;
  set_px(f.tech_r, 0, 1, 0.9f);
  f.conf[11] = 0.9f;
  f.conf[2] = 0.2f;
  const Breakdown b = compute_breakdown(f.labels, f.technique(), f.refs(), false);
  const RegionFigures* r1 = b.find("reflector:1");
  ASSERT_NE(r1, nullptr);
  EXPECT_TRUE(r1->handled);
  EXPECT_EQ(r1->pixels, 6u);
  EXPECT_EQ(r1->traceable.pixels, 2u);
  EXPECT_NEAR(*r1->traceable.psnr_ideal, 20.0, 1e-4);
  EXPECT_NEAR(*r1->traceable.psnr, 20.0 * std::log10(1.0 / 0.2), 1e-4);
  EXPECT_NEAR(*r1->traceable.psnr_reflection_ideal, 40.0, 1e-3);
  EXPECT_NEAR(*r1->traceable.psnr_reflection, 40.0, 1e-3);
  EXPECT_DOUBLE_EQ(*r1->traceable.coverage, 1.0);
  EXPECT_DOUBLE_EQ(*r1->traceable.correct_coverage, 1.0);  // 0.01 off in reflection: correct
  EXPECT_DOUBLE_EQ(*r1->missing.false_hit_rate, 0.5);
  EXPECT_DOUBLE_EQ(*r1->sky.false_hit_rate, 0.0);
  EXPECT_EQ(r1->hits.correct, 2u);
  EXPECT_EQ(r1->hits.false_hits, 1u);
  EXPECT_EQ(r1->hits.missed, 0u);
  EXPECT_EQ(r1->hits.correct_miss, 3u);
  // Identical images elsewhere: capped, finite, not null.
  EXPECT_DOUBLE_EQ(*r1->missing.psnr, kPsnrCap);
  EXPECT_LT(*r1->missing.psnr_reflection, 20.0);  // the wrong guess shows in the reflection

  const RegionFigures* r2 = b.find("reflector:2");
  EXPECT_DOUBLE_EQ(*r2->traceable.coverage, 0.0);
  EXPECT_EQ(r2->hits.missed, 1u);
  // The claimed sky pixel reflects what the truth does: a correct claim, no false hit.
  const RegionFigures* other = b.find("other");
  EXPECT_DOUBLE_EQ(*other->sky.false_hit_rate, 0.0);
  EXPECT_EQ(other->hits.correct, 2u);  // its traceable pixel (3,0) and the sky pixel
  const RegionFigures* all = b.find("all");
  EXPECT_EQ(all->hits.correct + all->hits.false_hits + all->hits.missed + all->hits.correct_miss, 12u);
  // A wrong colour on a claimed traceable pixel is a false hit, not a correct one.
  set_px(f.tech_r, 0, 0, 0.8f);
  const Breakdown b2 = compute_breakdown(f.labels, f.technique(), f.refs(), false);
  EXPECT_DOUBLE_EQ(*b2.find("reflector:1")->traceable.correct_coverage, 0.5);
  EXPECT_DOUBLE_EQ(*b2.find("reflector:1")->traceable.coverage, 1.0);
  EXPECT_EQ(b2.find("reflector:1")->hits.false_hits, 2u);
}

TEST(Breakdown, EmptySetsAreNullNever100) {
  Frame f;
  f.labels.roughness.assign(16, 0.0f);  // no glossy or rough pixel
  const Breakdown b = compute_breakdown(f.labels, f.technique(), f.refs(), false);
  const RegionFigures* rough = b.find("rough");
  EXPECT_EQ(rough->pixels, 0u);
  EXPECT_FALSE(rough->traceable.psnr);
  EXPECT_FALSE(rough->traceable.psnr_ideal);
  EXPECT_FALSE(rough->traceable.coverage);
  EXPECT_FALSE(rough->missing.false_hit_rate);
  EXPECT_FALSE(rough->sky.psnr);
  const nlohmann::json j = breakdown_json(b);
  EXPECT_TRUE(j["rough"]["traceable"]["psnr"].is_null());
  EXPECT_TRUE(j["rough"]["sky"]["false_hit_rate"].is_null());
  EXPECT_TRUE(j["all"]["traceable"]["psnr"].is_number());
  // No noise floor without the sample-count ideal.
  EXPECT_TRUE(j["all"]["traceable"]["noise_floor_psnr"].is_null());
}

TEST(Breakdown, PlanarOnlyTechniquesDoNotScoreOtherPixels) {
  Frame f;
  set_px(f.tech, 3, 0, 0.0f);  // the environment left on a non-planar pixel: must not count
  const Breakdown b = compute_breakdown(f.labels, f.technique(), f.refs(), true);
  const RegionFigures* other = b.find("other");
  EXPECT_EQ(other->pixels, 3u);
  EXPECT_EQ(other->handled_pixels, 0u);
  EXPECT_FALSE(other->handled);
  EXPECT_FALSE(other->traceable.psnr);
  const RegionFigures* all = b.find("all");
  EXPECT_FALSE(all->handled);
  EXPECT_EQ(all->handled_pixels, 9u);
  EXPECT_DOUBLE_EQ(*all->traceable.psnr_ideal, kPsnrCap);  // scored on the planar pixels only
  EXPECT_TRUE(b.find("planar")->handled);
  // The same frame, all handled: the non-planar pixel's error shows.
  const Breakdown full = compute_breakdown(f.labels, f.technique(), f.refs(), false);
  EXPECT_LT(*full.find("all")->traceable.psnr_ideal, 20.0);
  // The hit classes mark those pixels as not handled.
  const auto hits = hit_classes(f.labels, f.technique(), f.refs(), true);
  EXPECT_EQ(hits[3], HitClass::NotHandled);
  EXPECT_EQ(hits[15], HitClass::NotReflective);
  EXPECT_EQ(hits[0], HitClass::Correct);
}

TEST(Breakdown, NoiseFloorOnNonMirrorTraceablePixels) {
  Frame f;
  RgbaImageF noisy = filled(0.5f);
  set_px(noisy, 2, 0, 0.6f);  // glossy traceable pixel: 0.1 off -> 20 dB
  set_px(noisy, 0, 0, 0.9f);  // a mirror pixel: ignored (no sampling noise there)
  ReferenceImages r = f.refs();
  r.ideal_at_samples = &noisy;
  const Breakdown b = compute_breakdown(f.labels, f.technique(), r, false);
  EXPECT_NEAR(*b.find("glossy")->traceable.noise_floor_psnr, 20.0, 1e-4);
  EXPECT_NEAR(*b.find("all")->traceable.noise_floor_psnr, 20.0 * std::log10(1.0 / std::sqrt(0.01 / 2.0)), 1e-4);
  EXPECT_FALSE(b.find("mirror")->traceable.noise_floor_psnr);  // no rough pixel: null
}

TEST(Breakdown, InherentPerClass) {
  Frame f;
  set_px(f.truth, 1, 1, 0.6f);  // a missing pixel: ideal 0.5 vs truth 0.6
  const InherentFigures in = compute_inherent(f.labels, f.refs());
  EXPECT_DOUBLE_EQ(*in.traceable, kPsnrCap);
  EXPECT_NEAR(*in.missing, 20.0 * std::log10(1.0 / std::sqrt(0.01 / 4.0)), 1e-4);
  EXPECT_DOUBLE_EQ(*in.sky, kPsnrCap);
  Frame g;
  g.labels.classes.assign(16, PixelClass::Traceable);
  EXPECT_FALSE(compute_inherent(g.labels, g.refs()).sky);
}

TEST(Breakdown, OraclesCountPixelsWithin1Of255) {
  Frame f;
  RgbaImageF planar = filled(0.5f);
  set_px(planar, 0, 0, 0.5f + 0.5f / 255.0f);  // within
  set_px(planar, 1, 0, 0.5f + 2.0f / 255.0f);  // not within
  set_px(planar, 2, 0, 0.0f);                   // glossy: not compared
  std::vector<bool> eligible(16, true);
  eligible[4] = false;  // (0,1) normal-mapped, say
  const OracleAgreement o = compare_oracles(f.labels, planar, f.truth_r, eligible);
  EXPECT_EQ(o.pixels, 5u);  // reflector:1 mirror pixels in 3 reflective rows, less one
  EXPECT_NEAR(*o.within_1_255, 4.0 / 5.0, 1e-12);
  PixelLabels none = f.labels;
  none.reflector.assign(16, 0);
  EXPECT_FALSE(compare_oracles(none, planar, f.truth_r, eligible).psnr);
}

TEST(Breakdown, MismatchedSizesThrow) {
  Frame f;
  RgbaImageF small{2, 2, std::vector<float>(16, 0.0f)};
  TechniqueImages t = f.technique();
  t.final = &small;
  EXPECT_THROW(compute_breakdown(f.labels, t, f.refs(), false), std::invalid_argument);
  std::vector<float> conf(3);
  t = f.technique();
  t.confidence = &conf;
  EXPECT_THROW(compute_breakdown(f.labels, t, f.refs(), false), std::invalid_argument);
}
