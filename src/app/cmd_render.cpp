// `ssrlab render`: one frame of a scene with one technique, written as PNG or EXR.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "eval/grid.h"
#include "eval/metrics.h"
#include "eval/results.h"
#include "eval/runner.h"
#include "gl/gl.h"
#include "reference/reference.h"
#include "render/image_io.h"
#include "render/renderer.h"
#include "scene/scene_io.h"
#include "registry/presets.h"
#include "techniques/technique.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace fs = std::filesystem;

namespace ssr {

void add_frame_options(CLI::App* command, FrameOptions* o) {
  const std::span<const ParamDesc> table = frame_settings_table();
  o->values.assign(table.size(), std::nullopt);  // before the options point into it
  FrameSettings defaults;
  const ParamSet p = frame_settings_params(defaults);
  for (std::size_t i = 0; i < table.size(); ++i)
    command->add_option(frame_setting_option(table[i]), o->values[i],
                        std::string(table[i].help) + " Range " + p.range_string(i) + ", default " +
                            p.default_string(i) + (*table[i].unit ? std::string(" (") + table[i].unit + ")." : "."));
}

FrameSettings frame_settings(const FrameOptions& o) {
  FrameSettings s;
  const std::span<const ParamDesc> table = frame_settings_table();
  for (std::size_t i = 0; i < table.size() && i < o.values.size(); ++i)
    if (o.values[i]) set_frame_setting(s, table[i].name, *o.values[i], frame_setting_option(table[i]));
  return s;
}

std::unique_ptr<gl::HeadlessContext> open_gl(const std::string& path,
                                             const std::vector<std::pair<int, int>>& sizes) {
  auto ctx = gl::HeadlessContext::create(gl::parse_backend(path));
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  for (const auto& [w, h] : sizes)
    if (w > max_side || h > max_side)
      throw InputError("size " + std::to_string(w) + "x" + std::to_string(h) +
                       " is more than this GL supports (each side at most " +
                       std::to_string(max_side) + ").");
  const auto& i = ctx->info();
  std::fprintf(stderr, "ssrlab: GL via %s: %s | %s\n", i.path.c_str(), i.renderer.c_str(),
               i.version.c_str());
  return ctx;
}

namespace {

// The views only `render` writes (each a .png), beside the renderer's (view_table).
enum class RenderOnlyView { None, Classes, HitClasses, Difference };
struct RenderOnlyViewInfo {
  RenderOnlyView view;
  const char* name;
  const char* description;  // for --help
};
constexpr RenderOnlyViewInfo kRenderOnlyViews[] = {
    {RenderOnlyView::Classes, "classes", "the reference's traceable / missing / sky pixels; --technique reference only"},
    {RenderOnlyView::HitClasses, "hit-classes", "a technique's correct / false / missed hits against the reference"},
    {RenderOnlyView::Difference, "difference", "|technique - truth| on reflective pixels, 0.25 = hottest"},
};

// Views of change between frames: render draws one frame, with no frame before it, so they would
// be black (motion), one frame's worth (history) or the spatial stage's image again (temporal)
// and look like results. The viewer shows them as frames go by.
bool spans_frames(ViewMode v) { return v == ViewMode::Motion || v == ViewMode::History || v == ViewMode::Temporal; }

std::vector<std::string> render_only_view_names() {
  std::vector<std::string> names;
  for (const RenderOnlyViewInfo& v : kRenderOnlyViews) names.push_back(v.name);
  return names;
}

RenderOnlyView render_only_view(const std::string& name) {
  for (const RenderOnlyViewInfo& v : kRenderOnlyViews)
    if (name == v.name) return v.view;
  return RenderOnlyView::None;
}

struct RenderOptions {
  std::string scene = "gallery";
  std::string technique = "linear";
  std::string preset;
  std::vector<std::string> sets;
  std::string size = "1280x720";
  std::string camera;
  std::string out;
  std::string view = "final";
  std::string gl = "auto";
  std::string shader_dir;
  FrameOptions frame;  // --exposure, --reflective-f0
};

int run_render(const RenderOptions& o) {
  // Validate every input before any GL work or file is touched.
  const auto [w, h] = parse_size(o.size);
  const ImageFormat format = image_format_for(o.out);
  require_output_files({{"--out", o.out}}, {o.scene});
  const RenderOnlyView own_view = render_only_view(o.view);
  const bool classes_view = own_view == RenderOnlyView::Classes;  // the reference's own classes
  const bool diff_view = own_view == RenderOnlyView::Difference;  // the compare grid's bottom row
  // hit-classes and difference score a technique: they run the reference too.
  const bool scored_view = own_view == RenderOnlyView::HitClasses || diff_view;
  if (classes_view && !technique_info(o.technique).truth)
    throw InputError("--view classes needs --technique reference.");
  if ((classes_view || scored_view) && format != ImageFormat::Png)
    throw InputError("--view " + o.view + " writes a .png.");
  const ViewMode view =
      own_view != RenderOnlyView::None ? ViewMode::Final : parse_view_mode(o.view, render_only_view_names());
  Scene scene = load_scene(o.scene);
  const Camera camera = o.camera.empty() ? scene.cameras.front() : scene.camera(o.camera);
  std::string technique_name = o.technique;
  std::vector<std::string> sets = o.sets;
  if (!o.preset.empty()) {
    const Preset& p = find_preset(o.preset);
    technique_name = p.technique;
    sets.insert(sets.begin(), p.assignments.begin(), p.assignments.end());
  }
  // hit-classes and difference run the reference too: reference.* assignments are its.
  const std::vector<std::string> reference_sets = scored_view ? sets_for(truth_name(), sets) : std::vector<std::string>{};
  if (scored_view)
    sets.erase(std::remove_if(sets.begin(), sets.end(), [](const std::string& s) {
                 return s.rfind("reference.", 0) == 0;
               }), sets.end());
  auto technique = create_technique(technique_name);
  apply_assignments(*technique, sets);
  if (spans_frames(view))
    throw InputError("--view " + o.view + " shows change over frames and render draws one; ssrlab-view shows it as "
                     "frames go by.");
  if (view_info(view).debug) {
    // A debug view the technique does not fill would be a black image that looks like a result.
    const TechniqueDecl decl = technique->declare();
    if (std::find(decl.debug_views.begin(), decl.debug_views.end(), view) == decl.debug_views.end()) {
      std::string fills;
      for (ViewMode v : decl.debug_views) fills += (fills.empty() ? "" : ", ") + std::string(view_info(v).name);
      throw InputError("technique '" + technique_name + "' does not fill the view '" + o.view + "' (" +
                       (fills.empty() ? std::string("it fills no debug view") : "its debug views: " + fills) + ").");
    }
  }
  auto reference = scored_view ? create_technique(truth_name()) : nullptr;
  if (reference) apply_assignments(*reference, reference_sets);
  const FrameSettings settings = frame_settings(o.frame);  // the table's ranges, before any GL
  const gl::ShaderSource shaders = gl::ShaderSource::from_option(o.shader_dir);
  if (scored_view && technique_info(technique_name).truth)
    throw InputError("--view " + o.view + " scores a technique against the reference; name another technique.");

  auto ctx = open_gl(o.gl, {{w, h}});
  Renderer renderer(scene, w, h, shaders);
  renderer.settings = settings;
  // The telemetry views show what an instrumented build of the technique recorded.
  const bool telemetry_view = view_info(view).telemetry;
  technique->load(telemetry_view ? renderer.shaders().with_defines({"SSR_TELEMETRY"}) : renderer.shaders());
  if (telemetry_view) renderer.telemetry().begin(w, h);

  if (scored_view) {
    reference->load(renderer.shaders());
    ScoredFrame frame(renderer, camera, *reference);
    const ScoredFrame::Score s = frame.score(*technique);
    if (diff_view) {
      write_png(o.out, heat_map(s.display, frame.truth(), frame.classes()));
      std::printf("wrote %s (%dx%d, scene %s, technique %s, view difference, 0.25 = hottest): PSNR %s dB, "
                  "traceable %s dB\n",
                  o.out.c_str(), w, h, scene.name.c_str(), technique_name.c_str(), db_text(s.error.psnr).c_str(),
                  db_text(s.error.psnr_traceable).c_str());
    } else {
      write_png(o.out, hit_class_map(frame.hit_classes_of(s, *technique), frame.truth()));
      const RegionFigures* all = s.breakdown.find("all");
      std::printf("wrote %s (%dx%d, scene %s, technique %s, view hit-classes): %zu correct, %zu false, "
                  "%zu missed, %zu correct misses\n",
                  o.out.c_str(), w, h, scene.name.c_str(), technique_name.c_str(), all->hits.correct,
                  all->hits.false_hits, all->hits.missed, all->hits.correct_miss);
    }
    if (s.error.nonfinite) {
      std::fprintf(stderr, "ssrlab: %zu non-finite pixels in %s's final image.\n", s.error.nonfinite,
                   technique_name.c_str());
      return 1;
    }
    return 0;
  }

  gl::PassTimer timer(ctx->info().software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu);
  timer.begin_frame();
  renderer.render(camera, *technique, view, &timer);
  timer.end_frame();
  timer.flush();

  const std::size_t bad = count_nonfinite(renderer.read_texture(renderer.reflection()).pixels) +
                          count_nonfinite(renderer.read_texture(renderer.color()).pixels);
  if (classes_view) {
    write_png(o.out, class_map(*reference_outputs(*technique).classes, w, h));
  } else if (format == ImageFormat::Png) {
    write_png(o.out, renderer.read_display());
  } else {
    write_exr(o.out, renderer.read_linear());
  }

  const gl::FrameTimes& times = timer.completed().back();
  const double total = gl::outer_ms(times);
  std::string passes;
  for (const auto& p : times) {
    char buf[96];  // the technique span's passes inside brackets
    std::snprintf(buf, sizeof buf, " %s%s %.2f%s", p.depth > 0 ? "[" : "", p.name.c_str(), p.ms, p.depth > 0 ? "]" : "");
    passes += buf;
  }
  std::printf("wrote %s (%dx%d, scene %s, technique %s, view %s); %s ms %.2f:%s\n",
              o.out.c_str(), w, h, scene.name.c_str(), technique_name.c_str(), o.view.c_str(),
              timer.clock_name(), total, passes.c_str());
  if (telemetry_view) {
    if (const auto s = renderer.telemetry().read().stats())
      std::printf("telemetry: %llu rays, iterations mean %.1f p50 %d p95 %d max %d, idle lanes %.1f%%\n",
                  static_cast<unsigned long long>(s->rays), s->mean, s->p50, s->p95, s->max,
                  s->idle_lanes.value_or(0.0) * 100.0);
  }
  if (bad) {
    std::fprintf(stderr, "ssrlab: %zu non-finite values in the reflection/colour targets.\n", bad);
    return 1;
  }
  return 0;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* c = app.add_subcommand("render", "Render one frame of a scene with a technique.");
  c->add_option("--scene", o->scene, "Built-in scene name or a .json/.obj path.")->capture_default_str();
  CLI::Option* technique = c->add_option("--technique", o->technique, "Technique name (see `ssrlab techniques`).")->capture_default_str();
  // A preset names its technique: a second one given beside it would be silently ignored.
  c->add_option("--preset", o->preset, "A named parameter set (sets the technique, so not with --technique), e.g. thesis-hq.")
      ->excludes(technique);
  c->add_option("--set", o->sets, "Parameter assignment technique.key=value (repeatable).");
  c->add_option("--size", o->size, "Image size: WIDTHxHEIGHT or " + size_names() + ".")->capture_default_str();
  c->add_option("--camera", o->camera, "Named camera of the scene (default: its first).");
  c->add_option("--out", o->out, "Output image, .png (8-bit sRGB) or .exr (linear half float).")->required();
  std::string views;
  for (const ViewInfo& v : view_table())
    if (!spans_frames(v.mode)) views += (views.empty() ? "" : "|") + std::string(v.name);
  for (const RenderOnlyViewInfo& v : kRenderOnlyViews) views += "|" + std::string(v.name) + " (" + v.description + ")";
  c->add_option("--view", o->view, "What to write: " + views + ".")->capture_default_str();
  add_frame_options(c, &o->frame);
  c->add_option("--gl", o->gl, "GL path: " + gl::backend_names() + ".")->capture_default_str();
  c->add_option("--shaders", o->shader_dir, "Load shaders from this directory instead of the embedded copy.");
  return {c, [o] { return run_render(*o); }};
}

}  // namespace ssr
