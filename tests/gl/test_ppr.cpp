// Pixel-Projected Reflections against the ground truth (issue: PPR compute path).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/cli_common.h"
#include "eval/runner.h"
#include "gl_test_env.h"
#include "tracer_test_util.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_io.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

using namespace ssr;

namespace {

// A built-in scene's default view at 320x180 with its ground truth (reference, 16 samples).
struct GalleryFrame {
  explicit GalleryFrame(const std::string& name)
      : scene(make_builtin_scene(name)), renderer(scene, 320, 180), reference(create_technique("reference")) {
    apply_assignments(*reference, {"reference.samples=16"});
    reference->load(renderer.shaders());
    frame = std::make_unique<ScoredFrame>(renderer, scene.cameras[0], *reference);
  }
  Scene scene;
  Renderer renderer;
  std::unique_ptr<Technique> reference;
  std::unique_ptr<ScoredFrame> frame;
};

struct PlanarScore {
  double psnr_traceable = 0, coverage = 0;
  std::size_t traceable = 0, nonfinite = 0;
};

// The tracing error and coverage of `technique` on the planar reflectors' traceable pixels.
PlanarScore score_on_planar(Renderer& r, ScoredFrame& frame, const std::string& technique,
                            const std::vector<std::string>& sets) {
  auto t = create_technique(technique);
  apply_assignments(*t, sets);
  t->load(r.shaders());
  const ScoredFrame::Score s = frame.score(*t);
  const std::vector<bool> planar = test::planar_mask(r);
  std::vector<PixelClass> cls = frame.classes();
  for (std::size_t i = 0; i < cls.size(); ++i)
    if (!planar[i]) cls[i] = PixelClass::NotReflective;
  std::vector<float> conf(cls.size());
  for (std::size_t i = 0; i < conf.size(); ++i) conf[i] = s.reflection.pixels[i * 4 + 3];
  const ErrorMetrics e = compute_metrics(s.display, frame.truth(), frame.ideal(), cls, conf);
  return {e.psnr_traceable.value(), e.coverage.value(), e.traceable, s.error.nonfinite};
}

}  // namespace

// The thesis's own claim (Kim 2018, 5.3): on mirror reflectors PPR covers the traceable pixels
// and traces them no worse than its brute-force HQ preset, on the same frame. Measured on
// llvmpipe at 320x180 when this test was written: ppr 23.3 dB, thesis-hq 21.3 dB, coverage 99.9%
// (over the planar reflectors' traceable pixels: PPR only reflects in planar reflectors).
TEST(Ppr, MatchesThesisHqOnGalleryMirror) {
  // One floor mirror, then five reflectors: floor tiles and wall mirrors overlapping on screen.
  for (const char* name : {"gallery", "gallery:reflectors=5"}) {
    GalleryFrame g(name);
    Renderer& r = g.renderer;
    ScoredFrame& frame = *g.frame;
    const PlanarScore ppr = score_on_planar(r, frame, "ppr", {});
    const PlanarScore hq = score_on_planar(r, frame, "linear",
                                           {"linear.max_steps=1024", "linear.step_size=0.1", "linear.thickness=0.1",
                                            "linear.max_distance=10000", "linear.depth_interp=false"});
    std::printf("%s, 320x180: ppr %.2f dB traceable, coverage %.1f%%; thesis-hq %.2f dB, coverage %.1f%% (%zu px)\n",
                name, ppr.psnr_traceable, ppr.coverage * 100, hq.psnr_traceable, hq.coverage * 100, ppr.traceable);
    EXPECT_GT(ppr.traceable, 10000u) << name;
    EXPECT_GE(ppr.coverage, 0.95) << name;
    EXPECT_GE(ppr.psnr_traceable, hq.psnr_traceable) << name;
    EXPECT_EQ(ppr.nonfinite, 0u) << name;
  }
  test::expect_no_gl_errors();
}

// Normal-mapped and rough reflectors: the thesis's reprojection follows the perturbed normal
// (the image changes when it is switched off), GGX samples stay finite for every sample count.
// Measured at 320x180 when written: ripples, coverage 91% (mirror-solution holes where the
// bumps reflect what nothing projects onto).
TEST(Ppr, NormalMapsAndRoughness) {
  GalleryFrame g("gallery:normal_map=ripples");
  Renderer& r = g.renderer;
  ScoredFrame& frame = *g.frame;
  const PlanarScore bumpy = score_on_planar(r, frame, "ppr", {});
  EXPECT_GE(bumpy.coverage, 0.85);
  EXPECT_EQ(bumpy.nonfinite, 0u);
  auto on = create_technique("ppr"), off = create_technique("ppr");
  apply_assignments(*off, {"ppr.normal_maps=false"});
  double diff = 0;
  {
    on->load(r.shaders());
    off->load(r.shaders());
    const RgbaImageF a = frame.score(*on).reflection, b = frame.score(*off).reflection;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) diff += std::abs(a.pixels[i] - b.pixels[i]);
  }
  EXPECT_GT(diff, 1.0) << "normal_maps=true must change the reflection of a rippled floor";
  for (int samples : {1, 4, 8, 16}) {
    const PlanarScore rough = score_on_planar(
        r, frame, "ppr", {"ppr.roughness=0.4", "ppr.samples=" + std::to_string(samples)});
    EXPECT_EQ(rough.nonfinite, 0u) << samples;
    EXPECT_GE(rough.coverage, 0.85) << samples;
  }
  test::expect_no_gl_errors();
}

// Hard cases: the floor reflector seen edge-on (eye in its plane), behind the camera (looking
// up and away), and pixels exactly on the plane (objects standing on the mirror). Finite,
// confidence in [0,1], and no projection onto a reflector the camera cannot see.
TEST(Ppr, HardCasesStayFinite) {
  Scene scene = make_builtin_scene("gallery");
  scene.cameras.push_back(Camera{.name = "edge-on", .position = {0, 0, 6}, .target = {0, 0, 0}});
  scene.cameras.push_back(Camera{.name = "behind", .position = {0, 1.5f, 6}, .target = {0, 4, 12}});
  scene.cameras.push_back(Camera{.name = "below", .position = {0, -1, 6}, .target = {0, 1, 0}});
  validate(scene);
  Renderer r(scene, 96, 54);
  auto ppr = create_technique("ppr");
  // The projection alone (no fallback tracer), whose answers these cases are about.
  apply_assignments(*ppr, {"ppr.samples=4", "ppr.fallback=none"});
  ppr->load(r.shaders());
  for (const Camera& cam : scene.cameras)
    for (const char* roughness : {"auto", "0.6"}) {
      apply_assignments(*ppr, {std::string("ppr.roughness=") + roughness});
      r.render(cam, *ppr, ViewMode::Final, nullptr);
      const RgbaImageF refl = r.read_texture(r.reflection());
      EXPECT_EQ(test::count_nonfinite(refl) + test::count_nonfinite(r.read_texture(r.color())), 0u) << cam.name;
      for (std::size_t i = 3; i < refl.pixels.size(); i += 4) {
        ASSERT_GE(refl.pixels[i], 0.0f) << cam.name;
        ASSERT_LE(refl.pixels[i], 1.0f) << cam.name;
      }
      if (cam.name == "edge-on" || cam.name == "below") {
        // Eye in the floor's plane, or under it: the floor reflects nothing the camera sees.
        std::size_t confident = 0;
        for (std::size_t i = 3; i < refl.pixels.size(); i += 4) confident += refl.pixels[i] > 0.0f;
        EXPECT_EQ(confident, 0u) << cam.name;
      }
    }
  test::expect_no_gl_errors();
}

// PPR on the planar reflectors against the screen-space ideal, at least as good as hiz there
// (issue 12; llvmpipe, reference at 64 samples). Measured, ppr / hiz, dB vs the ideal and
// correct coverage (640x360 unless named):
//   gallery              34.94 / 33.24, 99.7% / 99.5% (before the resolve's refinement 31.47,
//                        before the nearer-surface rule 33.56)
//   gallery 1920x1080    35.64 / 34.55, 99.7% / 99.5% (33.63 before the nearer-surface rule)
//   gallery:reflectors=8 33.89 / 32.53, 99.4% / 99.4% (30.97, 32.77)
//   corridor             26.45 / 23.60, 93.1% / 87.9% (25.95, 26.16, 26.15 before glossy rays
//                        whose approximated point is off the surface took the fallback's hit)
//   pedestal             34.41 / 33.27, 65.1% / 62.0% (33.41, 34.37, 34.36; its floor is glossy)
// The refinement (ppr_resolve.glsl: each pixel's own mirror ray on the source's tangent plane,
// nearest fetch, outlines to the fallback) took the stripes and outline spill of the magnified
// reflections; the nearer-surface rule (a neighbour's source met first goes to the fallback)
// the wall showing through the spheres' magnified reflections, which at 1080p had put ppr
// 0.9 dB under hiz. The margins to hiz are 1.1 to 2.9 dB. Coverage minimums: the measured less 1%.
TEST(Ppr, PlanarPixelsAgainstTheIdeal) {
  struct Case {
    std::string scene;
    double min_correct;
    int width = 640, height = 360;
  };
  for (const Case& c : {Case{"gallery", 0.987}, Case{"gallery", 0.987, 1920, 1080}, Case{"gallery:reflectors=8", 0.984},
                        Case{"corridor", 0.914}, Case{SSRLAB_TEST_DATA "/../../assets/scenes/pedestal.json", 0.641}}) {
    const test::TracerScore s = test::score_technique(c.scene, c.width, c.height, "ppr", {});
    const test::TracerScore h = test::score_technique(c.scene, c.width, c.height, "hiz", {});
    const RegionFigures* f = s.breakdown.find("planar");
    const RegionFigures* g = h.breakdown.find("planar");
    ASSERT_TRUE(f && f->traceable.psnr_ideal && f->traceable.correct_coverage);
    ASSERT_TRUE(g && g->traceable.psnr_ideal);
    std::printf("ppr on %s's reflectors (%dx%d): %.2f dB vs ideal (hiz %.2f), %.1f%% correct (hiz %.1f%%)\n",
                c.scene.c_str(), c.width, c.height, *f->traceable.psnr_ideal, *g->traceable.psnr_ideal,
                *f->traceable.correct_coverage * 100, g->traceable.correct_coverage.value_or(0) * 100);
    EXPECT_GE(*f->traceable.psnr_ideal, *g->traceable.psnr_ideal) << c.scene << " " << c.width;
    EXPECT_GE(*f->traceable.correct_coverage, c.min_correct) << c.scene;
  }
}

// Rough reflectors: on each of ramp's bands (roughness 0.0 ... 1.0, reflector:1 ... 11) hybrid
// ppr is at least hiz's score: the thesis's approximation serves the smooth bands, the fallback
// answers from roughness 0.35. Measured, 640x360, ppr / hiz dB vs the ideal: bands 0.0-0.3
// 58.32 / 46.26, 19.71 / 19.41, 16.59 / 16.44, 18.27 / 18.12; 0.4-1.0 equal (18.87 ... 16.61);
// without the rule ppr trailed there by 0.13 to 1.17 dB (0.4: 18.74 / 18.87, 0.5: 19.50 / 20.66).
TEST(Ppr, RampBandsAtLeastHiz) {
  const test::TracerScore s = test::score_technique("ramp", 640, 360, "ppr", {});
  const test::TracerScore h = test::score_technique("ramp", 640, 360, "hiz", {});
  for (int band = 1; band <= 11; ++band) {
    const std::string name = "reflector:" + std::to_string(band);
    const RegionFigures* f = s.breakdown.find(name);
    const RegionFigures* g = h.breakdown.find(name);
    ASSERT_TRUE(f && g && f->traceable.psnr_ideal && g->traceable.psnr_ideal) << name;
    std::printf("ramp %s (roughness %.1f): ppr %.2f dB, hiz %.2f dB\n", name.c_str(), 0.1 * (band - 1),
                *f->traceable.psnr_ideal, *g->traceable.psnr_ideal);
    EXPECT_GE(*f->traceable.psnr_ideal, *g->traceable.psnr_ideal - 0.01) << name;
  }
}

// Hybrid PPR: the fallback tracer serves what projection cannot (non-planar pixels, unfilled
// holes, the normal-mapped mirror pixels, whose rays leave the plane's solution). On the ripples
// floor the projection alone scores 17.33 dB against the ideal on the floor (640x360, llvmpipe)
// where its fallback hiz scores 29.86 over every reflective pixel; with the fallback ppr scores
// 29.86 dB (measured; 23.48 when projection served the normal-mapped pixels whose reprojected
// rays it could refine): within 1 dB of it. Every fallback runs, and serves as it does alone
// (measured the same to the digit: with linear 28.88 dB, linear-binary 27.53, dda 29.94).
TEST(Ppr, FallbackTracerOnRipples) {
  const char* scene = "gallery:normal_map=ripples";
  const auto all = [](const test::TracerScore& s) { return s.breakdown.find("all")->traceable.psnr_ideal.value_or(0); };
  const double hybrid = all(test::score_technique(scene, 640, 360, "ppr", {}));
  const double hiz = all(test::score_technique(scene, 640, 360, "hiz", {}));
  const double alone = test::score_technique(scene, 640, 360, "ppr", {"ppr.fallback=none"})
                           .breakdown.find("planar")->traceable.psnr_ideal.value_or(0);
  std::printf("ripples: ppr alone %.2f dB (planar), ppr + hiz %.2f dB, hiz %.2f dB (all)\n", alone, hybrid, hiz);
  EXPECT_GE(hybrid, hiz - 1.0);
  EXPECT_GT(hybrid, alone + 2.0);
  for (const char* f : {"linear", "linear-binary", "dda"}) {
    const test::TracerScore s = test::score_technique(scene, 640, 360, "ppr", {std::string("ppr.fallback=") + f});
    EXPECT_EQ(s.error.nonfinite, 0u) << f;
    EXPECT_TRUE(s.breakdown.find("other")->handled) << f;
    const double tracer = all(test::score_technique(scene, 640, 360, f, {}));
    std::printf("ripples: ppr + %s %.2f dB, %s %.2f dB (all)\n", f, all(s), f, tracer);
    EXPECT_NEAR(all(s), tracer, 0.1) << f;
    EXPECT_GT(all(s), alone + 2.0) << f;
  }
}

// The crops where a new user saw ppr's artifacts (issue 12): the floor's reflections of the red
// marker sphere and of the teal cylinder (magnified near reflections: stripes and stipple), and
// the band where the floor meets the back wall (the dark junction line). Each crop is the
// projection of the object's mirror image (or of the junction, +-3 rows), on traceable floor
// pixels; ppr's final image against the screen-space ideal, next to hiz's.
TEST(Ppr, ArtifactCropsAgainstTheIdeal) {
  const int w = 640, h = 360;
  const Scene scene = make_builtin_scene("gallery");
  Renderer r(scene, w, h);
  auto reference = create_technique("reference");
  apply_assignments(*reference, {"reference.samples=16"});
  reference->load(r.shaders());
  const Camera& cam = scene.cameras.front();
  ScoredFrame frame(r, cam, *reference);
  const CameraMatrices m = camera_matrices(cam, w, h);
  auto floor_traceable = [&](std::size_t i) {
    return frame.labels().reflector[i] == 1 && frame.classes()[i] == PixelClass::Traceable;
  };
  // The pixel box of a set of world points mirrored in the floor (y = 0), grown by `pad`.
  auto mirrored_box = [&](const std::vector<glm::vec3>& pts, int pad) {
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (glm::vec3 p : pts) {
      glm::vec2 px;
      float d;
      if (project_to_pixel(m, w, h, {p.x, -p.y, p.z}, px, d)) {
        lo = glm::min(lo, px);
        hi = glm::max(hi, px);
      }
    }
    std::vector<bool> mask(static_cast<std::size_t>(w) * h, false);
    for (int y = std::max(0, int(lo.y) - pad); y <= std::min(h - 1, int(hi.y) + pad); ++y)
      for (int x = std::max(0, int(lo.x) - pad); x <= std::min(w - 1, int(hi.x) + pad); ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        mask[i] = floor_traceable(i);
      }
    return mask;
  };
  auto mesh_points = [&](const char* name) {
    std::vector<glm::vec3> pts;
    for (const Mesh& mesh : scene.meshes)
      if (mesh.name == name)
        for (const Vertex& v : mesh.vertices) pts.push_back(v.position);
    return pts;
  };
  std::vector<glm::vec3> junction;
  for (float x = -6.0f; x <= 6.0f; x += 0.25f) junction.push_back({x, 0.0f, -7.0f});
  struct Crop {
    const char* name;
    std::vector<bool> mask;
    double min_psnr;
  };
  // Minimums: ppr's measured figure less 0.5 dB (llvmpipe, reference 16 samples a rough pixel).
  // Measured vs the ideal, ppr (hiz): marker 29.54 dB (27.52), cylinder 32.64 (31.62), junction
  // 100 (80.99: ppr's nearest fetch at its refined source is the ideal's pixel); vs the truth
  // 25.11 (24.28), 30.13 (29.81), 42.05 (42.10). Before the resolve's refinement ppr had 26.22,
  // 29.33 and 43.66 vs the ideal; before the nearer-surface rule 27.21, 32.98 and 100 (the
  // marker's reflection showed the wall through it; the cylinder's outline hands a few more
  // pixels to hiz now).
  Crop crops[] = {{"marker sphere", mirrored_box(mesh_points("marker"), 2), 29.0},
                  {"teal cylinder", mirrored_box(mesh_points("pedestal_teal"), 2), 32.1},
                  {"wall junction", mirrored_box(junction, 3), 60.0}};
  auto ppr = create_technique("ppr"), hiz = create_technique("hiz");
  ppr->load(r.shaders());
  hiz->load(r.shaders());
  const RgbaImageF ppr_img = frame.score(*ppr).display, hiz_img = frame.score(*hiz).display;
  test::note_images_for_failure("ppr-vs-ideal", ppr_img, frame.ideal());
  test::note_images_for_failure("hiz-vs-ideal", hiz_img, frame.ideal());
  for (const Crop& c : crops) {
    std::size_t n = 0;
    for (bool b : c.mask) n += b;
    ASSERT_GT(n, 50u) << c.name;
    const std::optional<double> p = psnr_where(ppr_img, frame.ideal(), c.mask);
    const std::optional<double> q = psnr_where(hiz_img, frame.ideal(), c.mask);
    ASSERT_TRUE(p && q);
    const std::optional<double> pt = psnr_where(ppr_img, frame.truth(), c.mask);
    const std::optional<double> qt = psnr_where(hiz_img, frame.truth(), c.mask);
    std::printf("%s (%zu px): ppr %.2f dB, hiz %.2f dB vs the ideal; ppr %.2f, hiz %.2f vs the truth\n", c.name, n,
                *p, *q, pt.value_or(-1), qt.value_or(-1));
    EXPECT_GE(*p, c.min_psnr) << c.name;
  }
}

// Hole filling never claims the sky (issue 12): a pixel patched from a neighbour's source keeps it
// only where its own mirror ray meets that surface (ppr_refine) and the fallback tracer found a
// hit too; else the fallback's answer stands, which is nothing where the ray leaves. Measured
// (640x360, llvmpipe): gallery 24087 holes, 3 served by patching; its 8 tiles 28465 holes, 124
// served; none on a sky pixel with confidence over 0.5. Patching with the refinement alone
// claimed 75 and 85 sky pixels, with a check for background beside the source still 1.
TEST(Ppr, PatchedHolesNeverClaimTheSky) {
  std::size_t served_total = 0;
  for (const char* name : {"gallery", "gallery:reflectors=8"}) {
    const Scene scene = load_scene(name);
    Renderer r(scene, 640, 360);
    r.debug_outputs = true;  // offsets and holes, read below
    auto reference = create_technique("reference");
    apply_assignments(*reference, {"reference.samples=4"});  // classes only: mirror floors
    reference->load(r.shaders());
    ScoredFrame frame(r, scene.cameras.front(), *reference);
    auto ppr = create_technique("ppr");
    ppr->load(r.shaders());
    const ScoredFrame::Score s = frame.score(*ppr);
    const RgbaImageF debug = r.read_texture(r.debug());  // offset.xy, hole before, hole after
    std::size_t holes = 0, served = 0, claimed_sky = 0, sky = 0;
    for (std::size_t i = 0; i < frame.classes().size(); ++i) {
      if (frame.labels().reflector[i] == 0) continue;
      const bool is_sky = frame.classes()[i] == PixelClass::Sky;
      sky += is_sky;
      if (!(debug.pixels[i * 4 + 2] > 0.5f)) continue;  // not a hole before patching
      ++holes;
      if (debug.pixels[i * 4 + 3] > 0.5f) continue;  // not served by patching
      ++served;
      claimed_sky += is_sky && s.confidence[i] > 0.5f;
    }
    std::printf("%s: %zu holes, %zu served by patching, %zu of them sky with confidence > 0.5 (%zu sky pixels)\n",
                name, holes, served, claimed_sky, sky);
    EXPECT_GT(holes, 300u) << name;
    EXPECT_GT(sky, 1000u) << name;
    EXPECT_EQ(claimed_sky, 0u) << name;
    served_total += served;
  }
  EXPECT_GT(served_total, 50u);  // patching still serves
  test::expect_no_gl_errors();
}

// The resolve empties the intermediate the next frame projects into (there is no clear pass):
// frame after frame, and after the camera moves, ppr's image is what a fresh instance renders.
TEST(Ppr, EachFrameStartsFromAnEmptyIntermediate) {
  const Scene scene = make_builtin_scene("gallery");
  Renderer r(scene, 160, 90);
  auto ppr = create_technique("ppr");
  ppr->load(r.shaders());
  Camera moved = scene.cameras[0];
  moved.position += glm::vec3(0.4f, 0.3f, -0.5f);
  const Camera cams[] = {scene.cameras[0], scene.cameras[0], moved, moved, scene.cameras[0]};
  for (int f = 0; f < 5; ++f) {
    r.render(FrameRequest(cams[f], FrameTime{f + 1, 0.0f}), *ppr, ViewMode::Final, nullptr);
    const RgbaImageF running = r.read_texture(r.reflection());
    auto fresh = create_technique("ppr");
    fresh->load(r.shaders());
    r.render(FrameRequest(cams[f], FrameTime{f + 1, 0.0f}), *fresh, ViewMode::Final, nullptr);
    const RgbaImageF want = r.read_texture(r.reflection());
    test::expect_same_image(running, want, "ppr-frame-" + std::to_string(f + 1));
  }
  test::expect_no_gl_errors();
}
