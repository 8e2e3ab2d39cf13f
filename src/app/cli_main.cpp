// ssrlab: the headless command line (DESIGN §7). Exit codes: 0 ok, 1 runtime failure, 2 bad input.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "render/image_io.h"
#include "render/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_io.h"
#include "techniques/technique.h"

namespace fs = std::filesystem;
using namespace ssr;

namespace {

struct RenderOptions {
  std::string scene = "gallery";
  std::string technique = "linear";
  std::vector<std::string> sets;
  std::string size = "1280x720";
  std::string camera;
  std::string out;
  std::string view = "final";
  std::string gl = "auto";
  std::string shader_dir;
  float exposure = 0.0f;
};

std::unique_ptr<gl::HeadlessContext> open_gl(const std::string& path) {
  auto ctx = gl::HeadlessContext::create(gl::parse_backend(path));
  const auto& i = ctx->info();
  std::fprintf(stderr, "ssrlab: GL via %s: %s | %s\n", i.path.c_str(), i.renderer.c_str(),
               i.version.c_str());
  return ctx;
}

std::size_t count_nonfinite(const std::vector<float>& v) {
  std::size_t n = 0;
  for (float x : v) n += !std::isfinite(x);
  return n;
}

int cmd_render(const RenderOptions& o) {
  // Validate every input before any GL work or file is touched.
  const auto [w, h] = parse_size(o.size);
  const ImageFormat format = image_format_for(o.out);
  const fs::path out_dir = fs::absolute(o.out).parent_path();
  if (!fs::is_directory(out_dir))
    throw InputError("output directory '" + out_dir.string() + "' does not exist.");
  const ViewMode view = parse_view_mode(o.view);
  Scene scene = load_scene(o.scene);
  const Camera camera = o.camera.empty() ? scene.cameras.front() : scene.camera(o.camera);
  auto technique = create_technique(o.technique);
  apply_assignments(*technique, o.sets);
  if (!std::isfinite(o.exposure) || std::abs(o.exposure) > 20)
    throw InputError("exposure must be in [-20, 20] stops.");
  if (!o.shader_dir.empty() && !fs::is_directory(o.shader_dir))
    throw InputError("shader directory '" + o.shader_dir + "' does not exist.");

  auto ctx = open_gl(o.gl);
  gl::ShaderSource shaders = o.shader_dir.empty() ? gl::ShaderSource() : gl::ShaderSource(fs::path(o.shader_dir));
  Renderer renderer(scene, w, h, shaders);
  renderer.settings.exposure = o.exposure;
  technique->load(renderer.shaders());

  gl::PassTimer timer(ctx->info().software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu);
  timer.begin_frame();
  renderer.render(camera, *technique, view, &timer);
  timer.end_frame();
  timer.flush();

  const std::size_t bad = count_nonfinite(renderer.read_texture(renderer.reflection()).pixels) +
                          count_nonfinite(renderer.read_texture(renderer.color()).pixels);
  if (format == ImageFormat::Png)
    write_png(o.out, renderer.read_display());
  else
    write_exr(o.out, renderer.read_linear());

  double total = 0;
  std::string passes;
  for (const auto& p : timer.completed().back()) {
    total += p.ms;
    char buf[64];
    std::snprintf(buf, sizeof buf, " %s %.2f", p.name.c_str(), p.ms);
    passes += buf;
  }
  std::printf("wrote %s (%dx%d, scene %s, technique %s, view %s); %s ms %.2f:%s\n",
              o.out.c_str(), w, h, scene.name.c_str(), o.technique.c_str(), o.view.c_str(),
              timer.clock_name(), total, passes.c_str());
  if (bad) {
    std::fprintf(stderr, "ssrlab: %zu non-finite values in the reflection/colour targets.\n", bad);
    return 1;
  }
  return 0;
}

int cmd_scenes() {
  std::printf("built-in scenes:\n");
  for (const auto& s : builtin_scenes()) std::printf("  %-12s %s\n", s.name.c_str(), s.description.c_str());
  const fs::path dir = fs::path(SSRLAB_ASSET_DIR) / "scenes";
  std::error_code ec;
  if (fs::is_directory(dir, ec)) {
    std::printf("scene files (%s):\n", dir.c_str());
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(dir, ec))
      if (e.path().extension() == ".json") files.push_back(e.path().filename().string());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) std::printf("  %s\n", f.c_str());
  }
  return 0;
}

int cmd_techniques() {
  for (const TechniqueInfo& info : technique_registry()) {
    auto t = info.create();
    ParamSet p = t->params();
    std::printf("%s\n  %s\n", info.name.c_str(), info.description.c_str());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const ParamDesc& d = p.table()[i];
      std::printf("  %-26s default %-8s range %-18s %s%s%s%s\n", p.key(i).c_str(),
                  p.default_string(i).c_str(), p.range_string(i).c_str(), d.help,
                  *d.unit ? " (" : "", d.unit, *d.unit ? ")" : "");
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ssrlab: screen-space reflection laboratory (headless)"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Print help for every command.");

  RenderOptions r;
  CLI::App* render = app.add_subcommand("render", "Render one frame of a scene with a technique.");
  render->add_option("--scene", r.scene, "Built-in scene name or a .json/.obj path.")->capture_default_str();
  render->add_option("--technique", r.technique, "Technique name (see `ssrlab techniques`).")->capture_default_str();
  render->add_option("--set", r.sets, "Parameter assignment technique.key=value (repeatable).");
  render->add_option("--size", r.size, "Image size WIDTHxHEIGHT.")->capture_default_str();
  render->add_option("--camera", r.camera, "Named camera of the scene (default: its first).");
  render->add_option("--out", r.out, "Output image, .png (8-bit sRGB) or .exr (linear half float).")->required();
  render->add_option("--view", r.view, "What to write: " + [] {
    std::string s;
    for (const auto& n : view_mode_names()) s += (s.empty() ? "" : "|") + n;
    return s;
  }())->capture_default_str();
  render->add_option("--exposure", r.exposure, "Exposure in stops before tone mapping.")->capture_default_str();
  render->add_option("--gl", r.gl, "GL path: auto|egl|osmesa.")->capture_default_str();
  render->add_option("--shaders", r.shader_dir, "Load shaders from this directory instead of the embedded copy.");

  CLI::App* scenes = app.add_subcommand("scenes", "List the built-in scenes and scene files.");
  CLI::App* techniques = app.add_subcommand("techniques", "List every technique with every parameter.");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ssrlab: %s\n", e.what());
    return 2;
  }

  try {
    if (render->parsed()) return cmd_render(r);
    if (scenes->parsed()) return cmd_scenes();
    if (techniques->parsed()) return cmd_techniques();
  } catch (const InputError& e) {
    std::fprintf(stderr, "ssrlab: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ssrlab: %s\n", e.what());
    return 1;
  }
  return 0;
}
