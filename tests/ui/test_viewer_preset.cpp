// Viewer presets: round trips, atomic writes, and one-sentence errors for bad files.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "viewer/preset.h"
#include "core/errors.h"
#include "scene/scene_io.h"
#include "registry/registry.h"

namespace fs = std::filesystem;

namespace ssr {
namespace {

// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("ssrlab-ui-" + std::to_string(::getpid()) + "-" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void expect_same(const Camera& a, const Camera& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.up, b.up);
  EXPECT_EQ(a.fov_y_deg, b.fov_y_deg);
  EXPECT_EQ(a.near_plane, b.near_plane);
  EXPECT_EQ(a.far_plane, b.far_plane);
}

void expect_same(const ViewerPreset& a, const ViewerPreset& b) {
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.camera_name, b.camera_name);
  ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
  if (a.camera) expect_same(*a.camera, *b.camera);
  EXPECT_EQ(a.technique_a, b.technique_a);
  EXPECT_EQ(a.technique_b, b.technique_b);
  EXPECT_EQ(a.params_a, b.params_a);
  EXPECT_EQ(a.params_b, b.params_b);
  EXPECT_EQ(a.params_truth, b.params_truth);
  EXPECT_EQ(a.compare, b.compare);
  EXPECT_EQ(a.split, b.split);
  EXPECT_EQ(a.diff_scale, b.diff_scale);
  EXPECT_EQ(a.view, b.view);
  EXPECT_EQ(a.exposure, b.exposure);
  EXPECT_EQ(a.reflective_f0, b.reflective_f0);
  ASSERT_EQ(a.lights.has_value(), b.lights.has_value());
  if (a.lights) {
    ASSERT_EQ(a.lights->size(), b.lights->size());
    for (std::size_t i = 0; i < a.lights->size(); ++i) {
      const Light &x = (*a.lights)[i], &y = (*b.lights)[i];
      EXPECT_EQ(x.type, y.type);
      EXPECT_EQ(x.color, y.color);
      EXPECT_EQ(x.intensity, y.intensity);
      if (x.type == Light::Type::Point) {
        EXPECT_EQ(x.position, y.position);
        EXPECT_EQ(x.range, y.range);
      } else {  // directions are normalised on reading: equal up to rounding
        EXPECT_LT(glm::length(x.direction - y.direction), 1e-6f);
      }
    }
  }
  ASSERT_EQ(a.environment.has_value(), b.environment.has_value());
  if (a.environment) {
    const Environment &x = *a.environment, &y = *b.environment;
    EXPECT_EQ(x.type, y.type);
    EXPECT_EQ(x.intensity, y.intensity);
    if (x.type == Environment::Type::Sky) {
      EXPECT_EQ(x.zenith, y.zenith);
      EXPECT_EQ(x.horizon, y.horizon);
      EXPECT_EQ(x.ground, y.ground);
    } else {
      EXPECT_EQ(x.constant, y.constant);
    }
  }
  EXPECT_EQ(a.ambient, b.ambient);
}

// A preset that sets everything, with values that are not short decimals.
ViewerPreset full_preset() {
  ViewerPreset p;
  p.scene = "gallery";
  p.camera_name = "overview";
  Camera c;
  c.position = {1.1f, 2.0f / 3.0f, -7.25f};
  c.target = {0.0f, 0.5f, 0.1f};
  c.fov_y_deg = 47.123456f;
  c.near_plane = 0.0123f;
  c.far_plane = 345.5f;
  c.name = p.camera_name;
  p.camera = c;
  auto a = create_technique("linear");
  apply_params(*a, {"max_steps=77", "step_size=0.123456789", "depth_interp=true"});
  p.technique_a = "linear";
  p.params_a = capture_params(*a);
  auto b = create_technique("ppr");
  apply_params(*b, {"hole_fill=" + std::string(b->params().table()[0].choices.back())});
  p.technique_b = "ppr";
  p.params_b = capture_params(*b);
  // The grid's truth (its parameters were dropped: A vs truth 18.00 dB with samples=4, 18.27
  // after a save and load).
  auto truth = create_technique(truth_name());
  apply_params(*truth, {"samples=4"});
  p.params_truth = capture_params(*truth);
  p.compare = "split";
  p.split = 0.3f;
  p.diff_scale = 0.1f;
  p.view = "reflection";
  p.exposure = -1.7f;
  p.reflective_f0 = 0.25f;
  Light point;
  point.position = {1, 2, 3};
  point.color = {1.0f, 0.5f, 0.25f};
  point.intensity = 12.5f;
  point.range = 7.0f;
  Light sun;
  sun.type = Light::Type::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.intensity = 3.0f;
  p.lights = std::vector<Light>{point, sun};
  Environment env;
  env.type = Environment::Type::Constant;
  env.constant = {0.1f, 0.2f, 0.3f};
  env.intensity = 2.0f;
  p.environment = env;
  p.ambient = 0.7f;
  return p;
}

TEST(ViewerPreset, SaveLoadRoundTrip) {
  TempDir dir;
  const fs::path file = dir.path() / "p.json";
  const ViewerPreset p = full_preset();
  save_preset(file, p);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"p.json"}) << "no temporary file left";
  const ViewerPreset q = load_preset(file);
  expect_same(p, q);
  // Defaults and name-only cameras round-trip too.
  ViewerPreset d;
  d.camera_name = "default";
  save_preset(file, d);
  expect_same(d, load_preset(file));
}

TEST(ViewerPreset, TextIsReadable) {
  const std::string text = preset_to_json_text(full_preset());
  EXPECT_NE(text.find("\"version\": 1"), std::string::npos);
  EXPECT_NE(text.find("\"split\": 0.3,"), std::string::npos) << "floats as short decimals";
  EXPECT_NE(text.find("\"position\": [1.0, 2.0, 3.0]"), std::string::npos) << "vectors on one line";
  EXPECT_NE(text.find("\"depth_interp\": true"), std::string::npos);
  EXPECT_NE(text.find("\"max_steps\": 77"), std::string::npos);
}

TEST(ViewerPreset, CaptureAndApplyEveryTechniqueExactly) {
  for (const TechniqueInfo& info : technique_registry()) {
    SCOPED_TRACE(info.name);
    auto t = info.create();
    ParamSet p = t->params();
    // Every value away from its default (floats to a value with many digits).
    for (std::size_t i = 0; i < p.size(); ++i) {
      const ParamDesc& d = p.table()[i];
      const double v = d.type == ParamType::Float ? d.min + (d.max - d.min) * 0.3183098861837907
                                                  : (p.get_default(i) == d.max ? d.min : d.max);
      p.set(i, v);
    }
    const std::vector<std::string> captured = capture_params(*t);
    ASSERT_EQ(captured.size(), p.size());
    auto fresh = info.create();
    apply_params(*fresh, captured);
    ParamSet q = fresh->params();
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(q.get(i), p.get(i)) << p.key(i);
    // Applying an empty list means the defaults.
    apply_params(*fresh, {});
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(q.get(i), q.get_default(i)) << p.key(i);
  }
}

TEST(ViewerPreset, ApplyChecksEverythingBeforeChangingAnything) {
  auto t = create_technique("linear");
  apply_params(*t, {"max_steps=99"});
  const std::vector<std::string> before = capture_params(*t);
  for (const std::vector<std::string>& bad :
       {std::vector<std::string>{"step_size=0.5", "max_steps=0"}, {"step_size=0.5", "nope=1"},
        {"linear.max_steps=3"}, {"max_steps"}, {"depth_interp=maybe"}}) {
    EXPECT_THROW(apply_params(*t, bad), InputError) << bad.back();
    EXPECT_EQ(capture_params(*t), before) << bad.back();
  }
}

TEST(ViewerPreset, AtomicWriteKeepsTheOldFileOnFailure) {
  TempDir dir;
  const fs::path file = dir.path() / "p.json";
  save_preset(file, ViewerPreset{});
  const std::string old = read_text(file);
  // The write fails part-way: a file size limit (works as root too, unlike permissions).
  std::signal(SIGXFSZ, SIG_IGN);
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  rlimit small = saved;
  small.rlim_cur = 64;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  EXPECT_THROW(save_preset(file, full_preset()), RuntimeError);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &saved), 0);
  std::signal(SIGXFSZ, SIG_DFL);
  EXPECT_EQ(read_text(file), old) << "the existing file survives";
  EXPECT_EQ(dir.files(), std::vector<std::string>{"p.json"}) << "no temporary file left";
  // A directory that does not exist: nothing is created.
  EXPECT_THROW(save_preset(dir.path() / "missing" / "p.json", ViewerPreset{}), RuntimeError);
  // A preset that would not load back is refused before anything is written.
  ViewerPreset bad;
  bad.split = 2.0f;
  EXPECT_THROW(save_preset(file, bad), InputError);
  bad = ViewerPreset{};
  bad.exposure = NAN;
  EXPECT_THROW(save_preset(file, bad), InputError);
  EXPECT_EQ(read_text(file), old);
  EXPECT_EQ(dir.files(), std::vector<std::string>{"p.json"});
}

// Every message: one sentence (one line, one final full stop) naming the file.
void expect_one_sentence(const std::string& msg, const std::string& where) {
  EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  ASSERT_FALSE(msg.empty());
  EXPECT_EQ(msg.back(), '.') << msg;
  EXPECT_EQ(msg.rfind(where, 0), 0u) << msg;
}

TEST(ViewerPreset, MissingOrUnreadableFilesAreInputErrors) {
  TempDir dir;
  for (const fs::path& p : {dir.path() / "none.json", dir.path()}) {
    try {
      load_preset(p);
      ADD_FAILURE() << "no error for " << p;
    } catch (const InputError& e) {
      expect_one_sentence(e.what(), "viewer preset '" + p.string() + "'");
    }
  }
}

TEST(ViewerPreset, BadPresetsAreOneSentenceInputErrors) {
  struct Case {
    std::string json;  // after {"version": 1, ... unless it starts with '!'
    std::string key;   // the message names it
  };
  const std::vector<Case> cases = {
      {"!", "is empty"},
      {"!{\"version\": 1,", "syntax error"},
      {"![1]", "must hold a JSON object"},
      {"!{}", "'version' is required"},
      {"!{\"version\": 2}", "'version'"},
      {"!{\"version\": \"1\"}", "'version'"},
      {"!{\"version\": 1, \"split\": 0.5, \"split\": 0.6}", "'split' twice"},
      {"\"colour\": 1", "'colour'"},
      {"\"scene\": 3", "'scene'"},
      {"\"scene\": \"\"", "'scene'"},
      {"\"technique_a\": \"linear\"", "'technique_a'"},
      {"\"technique_a\": {}", "'technique_a.name'"},
      {"\"truth\": {\"name\": \"linear\"}", "'truth.name' must be 'reference'"},
      {"\"truth\": {\"name\": \"reference\", \"params\": {\"samples\": 0}}", "samples"},
      {"\"technique_b\": {\"name\": \"nope\"}", "'technique_b.name'"},
      {"\"technique_a\": {\"name\": \"linear\", \"mode\": 1}", "'technique_a.mode'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": []}", "'technique_a.params'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": {\"nope\": 1}}", "'linear.nope'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": {\"max_steps\": 0}}", "'linear.max_steps'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": {\"max_steps\": 1.5}}", "'linear.max_steps'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": {\"max_steps\": [1]}}",
       "'technique_a.params.max_steps'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": {\"depth_interp\": \"maybe\"}}",
       "'linear.depth_interp'"},
      {"\"technique_a\": {\"name\": \"linear\", \"params\": {\"linear.max_steps\": 4}}",
       "'linear.max_steps'"},
      {"\"technique_a\": {\"name\": \"none\", \"params\": {\"x\": 1}}", "'none.x'"},
      {"\"compare\": \"sideways\"", "'compare'"},
      {"\"compare\": 1", "'compare'"},
      {"\"split\": 1.5", "'split'"},
      {"\"split\": \"0.5\"", "'split'"},
      {"\"diff_scale\": 0", "'diff_scale'"},
      {"\"exposure\": 1e300", "'exposure'"},
      {"\"exposure\": -1e999", "number overflow"},
      {"\"reflective_f0\": 0", "'reflective_f0'"},
      {"\"reflective_f0\": 2", "'reflective_f0'"},
      {"\"view\": \"nope\"", "'view'"},
      {"\"lights\": {}", "'lights'"},
      {"\"lights\": [{\"type\": \"spot\"}]", "'lights[0].type'"},
      {"\"lights\": [{\"type\": \"point\"}]", "'lights[0].position'"},
      {"\"lights\": [{\"type\": \"point\", \"position\": [0, 1, 0], \"intensity\": -1}]",
       "'lights[0].intensity'"},
      {"\"lights\": [{\"type\": \"directional\", \"direction\": [0, 0, 0]}]", "'lights[0].direction'"},
      {"\"lights\": [{\"type\": \"directional\", \"direction\": [0, -1, 0], \"range\": 3}]",
       "'lights[0].range'"},
      {"\"environment\": {\"type\": \"hdr\"}", "'environment.type'"},
      {"\"environment\": {\"type\": \"sky\", \"color\": [1, 1, 1]}", "'environment.color'"},
      {"\"environment\": {\"intensity\": -1}", "'environment.intensity'"},
      {"\"ambient\": -0.5", "'ambient'"},
      {"\"camera\": 5", "'camera'"},
      {"\"camera\": {\"name\": \"\"}", "'camera.name'"},
      {"\"camera\": {\"position\": [0, 1, 0], \"target\": [0, 1, 0]}", "'camera.target'"},
      {"\"camera\": {\"position\": [0, 1, 5], \"fov_y\": 200}", "'camera.fov_y'"},
      {"\"camera\": {\"position\": [0, 1, 5], \"near\": 5, \"far\": 1}", "'camera.far'"},
      {"\"camera\": {\"position\": [0, 1, 5], \"zoom\": 2}", "'camera.zoom'"},
  };
  std::string many_lights = "\"lights\": [";
  for (int i = 0; i <= Scene::kMaxLights; ++i)
    many_lights += std::string(i ? ", " : "") + "{\"type\": \"point\", \"position\": [0, 1, 0]}";
  std::vector<Case> all = cases;
  all.push_back({many_lights + "]", "'lights'"});
  const std::string where = "viewer preset 'bad.json'";
  for (const Case& c : all) {
    const std::string text = c.json.starts_with("!") ? c.json.substr(1) : "{\"version\": 1, " + c.json + "}";
    SCOPED_TRACE(text.substr(0, 120));
    try {
      preset_from_json_text(text, where);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      expect_one_sentence(e.what(), where);
      EXPECT_NE(std::string(e.what()).find(c.key), std::string::npos) << e.what();
    }
  }
}

TEST(ViewerPreset, HandWrittenPresetWithCommentsAndDefaults) {
  const ViewerPreset p = preset_from_json_text(R"({
    // only a few keys: the rest take their defaults
    "version": 1,
    "technique_a": {"name": "dda", "params": {"stride": 2}},
    "camera": {"name": "overview"},
    "lights": []
  })", "viewer preset 'hand.json'");
  EXPECT_EQ(p.technique_a, "dda");
  EXPECT_EQ(p.params_a, std::vector<std::string>{"stride=2"});
  EXPECT_EQ(p.technique_b, "none");
  EXPECT_EQ(p.camera_name, "overview");
  EXPECT_FALSE(p.camera);
  ASSERT_TRUE(p.lights);
  EXPECT_TRUE(p.lights->empty());
  EXPECT_FALSE(p.environment);
  EXPECT_FALSE(p.ambient);
  EXPECT_EQ(p.compare, "off");
  auto t = create_technique("dda");
  apply_params(*t, p.params_a);
  EXPECT_EQ(t->params().get(static_cast<std::size_t>(t->params().find("stride"))), 2.0);
}

// Lights and environment from a scene file and from a preset read the same (one reader).
TEST(ViewerPreset, LightsReadAsSceneFilesReadThem) {
  const Scene s = load_scene("gallery");
  ViewerPreset p;
  p.lights = s.lights;
  p.environment = s.environment;
  p.ambient = s.ambient;
  const ViewerPreset q = preset_from_json_text(preset_to_json_text(p), "p");
  expect_same(p, q);
  Scene t = s;
  t.lights = *q.lights;
  t.environment = *q.environment;
  t.ambient = *q.ambient;
  EXPECT_NO_THROW(validate(t));
}

}  // namespace
}  // namespace ssr
