// `ssrlab compare`: every technique and the reference on the same frame; a labelled grid of the
// images and their difference heat maps, the results JSON, and a table on stdout.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "core/revision.h"
#include "registry/variants.h"
#include "eval/grid.h"
#include "eval/results.h"
#include "eval/runner.h"
#include "render/image_io.h"
#include "scene/scene_io.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace fs = std::filesystem;

namespace ssr {
namespace {

struct CompareOptions {
  std::string scene = "gallery";
  std::optional<std::string> techniques;  // not given: every technique but the reference
  std::vector<std::string> presets;
  std::vector<std::string> sets;
  std::string size = "640x360";
  std::string camera;
  std::string out;
  std::string json;
  std::string gl = "auto";
  int frames = 5;
  FrameOptions frame;  // --exposure, --reflective-f0
  bool breakdown = false;
  std::string regions;  // --regions: the breakdown's rows
};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

int run_compare(const CompareOptions& o) {
  const auto [w, h] = parse_size(o.size);
  if (image_format_for(o.out) != ImageFormat::Png) throw InputError("the grid is written as a .png.");
  require_output_files({{"--out", o.out}, {"--json", o.json}}, {o.scene});
  if (o.frames < 1 || o.frames > 1000) throw InputError("--frames must be in [1, 1000].");
  const FrameSettings settings = frame_settings(o.frame);  // the table's ranges, before any GL
  Scene scene = load_scene(o.scene);
  std::vector<std::string> regions;
  if (!o.regions.empty())
    for (const std::string& name : split_list(o.regions, "region"))
      regions.push_back(parse_region(name, static_cast<int>(scene.reflectors.size())).name());
  const bool breakdown = o.breakdown || !regions.empty();
  if (breakdown && !has_reflective_surfaces(scene, settings.reflective_f0))
    throw InputError("--breakdown needs reflective pixels, and scene '" + scene.name + "' has no reflective surface.");
  const Camera camera = o.camera.empty() ? scene.cameras.front() : scene.camera(o.camera);
  const std::vector<std::string> names = technique_names(o.techniques);
  const std::vector<Variant> variants = build_variants(names, o.sets, {}, o.presets);
  auto reference = create_technique(truth_name());
  apply_assignments(*reference, sets_for(truth_name(), o.sets));

  auto ctx = open_gl(o.gl, {{w, h}});
  const std::string clock = ctx->info().software ? "cpu" : "gpu";
  Renderer renderer(scene, w, h);
  renderer.settings = settings;
  reference->load(renderer.shaders());
  TimingOptions timing{1, o.frames, ctx->info().software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu};

  ScoredFrame frame(renderer, camera, *reference);

  RunResults run;
  run.scene = scene.name;
  run.width = w;
  run.height = h;
  run.inherent_psnr = frame.inherent_psnr();
  run.reference_params = param_list(*reference);
  run.frame_settings = param_list(frame_settings_params(renderer.settings));
  run.inherent = frame.inherent();
  run.truth_noise = frame.truth_noise();
  std::vector<GridTile> top = {{"reference (truth)", to_rgba8(frame.truth())}};
  std::vector<GridTile> bottom = {{"classes: traceable/missing/sky", class_map(frame.classes(), w, h)}};
  for (const Variant& v : variants) {
    EvaluatedVariant ev = evaluate_variant(renderer, frame, camera, v, timing);
    const ErrorMetrics& e = ev.result.error;
    const std::string label = v.label() + "  " + fmt("%.2f ms ", ev.result.time_ms.median) + clock;
    top.push_back({label, to_rgba8(ev.score.display)});
    bottom.push_back({"diff vs truth, PSNR " + (e.psnr ? fmt("%.1f dB", *e.psnr) : std::string("- (nothing reflects)")),
                      heat_map(ev.score.display, frame.truth(), frame.classes())});
    run.results.push_back(ev.result);
    // The two oracles check each other (ARCHITECTURE §5) wherever planar runs.
    if (technique_info(v.technique).oracle && !run.oracles) run.oracles = oracle_agreement(frame, ev.score);
  }
  time_floor(renderer, camera, timing, run);  // after the variants (runner.h says why)
  std::vector<GridTile> tiles = top;
  tiles.insert(tiles.end(), bottom.begin(), bottom.end());
  write_png(o.out, make_grid(tiles, static_cast<int>(top.size())));
  const gl::ContextInfo& gi = ctx->info();
  if (!o.json.empty())
    write_text_file_atomic(o.json, to_json({gi.renderer, gi.version, clock}, build_revision(), run).dump(2) + "\n");
  std::printf("%s", results_table(run, clock).c_str());
  if (breakdown) std::printf("\n%s", breakdown_table(run, regions).c_str());
  std::printf("reference: %zu rays; grid %s%s%s\n", frame.reference_rays(), o.out.c_str(),
              o.json.empty() ? "" : ", results ", o.json.c_str());
  for (const TechniqueResult& r : run.results)
    if (r.error.nonfinite) return 1;
  return 0;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* c = app.add_subcommand("compare", "Run techniques and the reference on one frame; grid, JSON, table.");
  c->add_option("--scene", o->scene, "Built-in scene name or a .json/.obj path.")->capture_default_str();
  c->add_option("--techniques", o->techniques, "Comma-separated techniques (default: all but the reference).");
  c->add_option("--preset", o->presets, "Add a named preset as its own column (repeatable).");
  c->add_option("--set", o->sets, "Parameter assignment technique.key=value (repeatable; reference.* too).");
  c->add_option("--size", o->size, "Image size: WIDTHxHEIGHT or " + size_names() + ".")->capture_default_str();
  c->add_option("--camera", o->camera, "Named camera of the scene (default: its first).");
  c->add_option("--out", o->out, "The labelled grid (.png).")->required();
  c->add_option("--json", o->json, "Results JSON (README, Verdicts: every field).");
  c->add_option("--frames", o->frames, "Timed frames per technique (after one warm-up).")->capture_default_str();
  add_frame_options(c, &o->frame);
  c->add_flag("--breakdown", o->breakdown, "Also print every region x class of every technique.");
  c->add_option("--regions", o->regions,
                "The breakdown's rows (implies --breakdown): " + region_names() + ".");
  c->add_option("--gl", o->gl, "GL path: " + gl::backend_names() + ".")->capture_default_str();
  return {c, [o] { return run_compare(*o); }};
}

}  // namespace ssr
