// `ssrlab sequence`: a camera path frame by frame, every technique keeping its history, scored
// against each frame's truth, with temporal metrics; JSON, optional PNG frames, video and plots.
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "core/files.h"
#include "core/revision.h"
#include "registry/variants.h"
#include "eval/grid.h"
#include "eval/results.h"
#include "eval/sequence.h"
#include "eval/video.h"
#include "render/image_io.h"
#include "scene/scene_io.h"
#include "techniques/assignments.h"
#include "registry/registry.h"

namespace fs = std::filesystem;

namespace ssr {
namespace {

// Ctrl-C or a kill while frames or a video are written: the frame loop stops at the next frame
// and unwinds, so the temporary frame directory and video are removed instead of left behind.
// A second signal takes the default action (a hung GL call can still be stopped).
volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void stop_at_next_frame(int signal) {
  g_stop_signal = signal;
  std::signal(signal, SIG_DFL);
}
void stop_if_signalled() {
  if (g_stop_signal != 0)
    throw RuntimeError("stopped by signal " + std::to_string(g_stop_signal) +
                       "; the unfinished frames and video were removed.");
}

struct SequenceOptions {
  std::string scene = "gallery";
  std::string path;  // default: the scene's path option, its first path, else "still"
  int frames = 0;
  std::optional<std::string> techniques;  // not given: every technique but the reference
  std::vector<std::string> presets;
  std::vector<std::string> sets;
  std::vector<std::string> sweeps;
  std::string size = "320x180";
  int truth_every = 1;
  bool second_truth = false;
  float fps = 30.0f;
  FrameOptions frame;  // --exposure, --reflective-f0
  std::string json, out, video, plot;
  std::string gl = "auto";
  std::string shader_dir;  // empty: the embedded shaders
};

// One row a technique: its final image | the truth | |difference| heat map.
RgbaImage8 compose(const SequenceImages& im, const std::vector<std::string>& labels, int w, int h) {
  const RgbaImage8 black{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h * 4, 0)};
  std::vector<RgbaImage8> rows;
  char when[64];
  std::snprintf(when, sizeof when, "  frame %d  t=%.2fs%s", im.frame.index, im.frame.time, im.frame.cut ? "  CUT" : "");
  for (std::size_t v = 0; v < im.technique.size(); ++v) {
    const bool truth = im.truth != nullptr;
    rows.push_back(labelled_panels(
        {{labels[v] + when, im.technique[v]->pixels.empty() ? black : to_rgba8(*im.technique[v])},
         {truth ? "truth" : "truth: not this frame", truth ? to_rgba8(*im.truth) : black},
         {truth ? "|difference| (0.25 = hottest)" : "", truth ? heat_map(*im.technique[v], *im.truth, *im.classes) : black}}));
  }
  return vstack(rows);
}

int run_sequence_command(const SequenceOptions& o) {
  const auto [w, h] = parse_size(o.size);
  if (o.frames < 1 || o.frames > 100000) throw InputError("--frames must be in [1, 100000].");
  if (o.truth_every < 1 || o.truth_every > 100000) throw InputError("--truth-every must be in [1, 100000].");
  // At least 0.01: frame i's time i / fps stays a finite float for every frame count allowed.
  if (!(o.fps >= 0.01f) || o.fps > 1000.0f) throw InputError("--fps must be in [0.01, 1000].");
  if (!o.plot.empty() && files::lower_extension(o.plot) != ".svg") throw InputError("--plot is written as an .svg.");
  require_output_files({{"--json", o.json}, {"--plot", o.plot}, {"--video", o.video}}, {o.scene});
  // "frames/" (as shells complete it) is the directory "frames": its temporary sibling must not
  // land inside it.
  fs::path out_dir = fs::path(o.out).lexically_normal();
  if (!o.out.empty() && out_dir.filename().empty()) out_dir = out_dir.parent_path();
  if (!o.out.empty()) {
    const fs::path dir = out_dir, parent = fs::absolute(dir).parent_path();
    if (!fs::is_directory(parent)) throw InputError("--out: the directory '" + parent.string() + "' does not exist.");
    require_creatable("--out", o.out, parent);  // the frames go to a temporary directory there
    if (fs::exists(dir) && !(fs::is_directory(dir) && fs::is_empty(dir)))
      throw InputError("--out '" + o.out + "' must be a new or empty directory.");
    const fs::path out_path = fs::absolute(dir).lexically_normal();
    for (const auto& [option, file] : {std::pair{"--json", o.json}, {"--plot", o.plot}, {"--video", o.video}})
      if (!file.empty() && fs::absolute(file).lexically_normal() == out_path)
        throw InputError(std::string(option) + " and --out name the same path '" + file + "'.");
  }
  Scene scene = load_scene(o.scene);
  SequenceSpec spec{o.path, o.frames, o.truth_every, o.fps, o.second_truth};
  sequence_path(scene, o.path);  // an unknown path is an error before any work
  const std::vector<std::string> names = technique_names(o.techniques);
  const std::vector<Variant> variants = build_variants(names, o.sets, o.sweeps, o.presets);
  std::vector<std::string> labels;
  for (const Variant& v : variants) labels.push_back(v.label());
  auto reference = create_technique(truth_name());
  apply_assignments(*reference, sets_for(truth_name(), o.sets));

  // From here on temporaries exist until the end: a signal unwinds through their cleanup.
  const bool images = !o.video.empty() || !o.out.empty();
  if (images) {
    std::signal(SIGINT, stop_at_next_frame);
    std::signal(SIGTERM, stop_at_next_frame);
  }
  // The video's frame size is the composition's; the writer checks ffmpeg and the path now.
  std::optional<VideoWriter> video;
  if (!o.video.empty()) {
    const SequenceFrame probe{};
    const RgbaImageF blank{w, h, {}};
    SequenceImages im{probe, std::vector<const RgbaImageF*>(variants.size(), &blank), nullptr, nullptr};
    const RgbaImage8 first = compose(im, labels, w, h);
    video.emplace(o.video, first.width, first.height, static_cast<int>(std::lround(std::min(o.fps, 120.0f))));
  }
  const fs::path frames_tmp = o.out.empty() ? fs::path() : files::temp_path_beside(out_dir);
  if (!o.out.empty()) {
    fs::remove_all(frames_tmp);
    fs::create_directories(frames_tmp);
  }
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ec;
      if (!dir.empty()) fs::remove_all(dir, ec);
    }
  } cleanup{frames_tmp};

  const FrameSettings settings = frame_settings(o.frame);  // the table's ranges, before any GL
  const gl::ShaderSource shaders = gl::ShaderSource::from_option(o.shader_dir);
  auto ctx = open_gl(o.gl, {{w, h}});
  const gl::ContextInfo& gi = ctx->info();
  Renderer renderer(scene, w, h, shaders);
  renderer.settings = settings;
  reference->load(renderer.shaders());
  std::function<void(const SequenceImages&)> on_frame;
  if (images)
    on_frame = [&](const SequenceImages& im) {
      stop_if_signalled();
      const RgbaImage8 frame = compose(im, labels, w, h);
      if (video) video->add_frame(frame);
      if (!o.out.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", im.frame.index);
        write_png((frames_tmp / name).string(), frame);
      }
    };
  const SequenceResults r = run_sequence(renderer, variants, *reference, spec, on_frame);

  const std::string clock = gi.software ? "cpu" : "gpu";
  stop_if_signalled();  // a signal after the last frame: nothing is finished either
  if (video) video->finish();
  if (!o.out.empty()) {
    if (fs::exists(out_dir)) fs::remove(out_dir);  // empty (checked above)
    fs::rename(frames_tmp, out_dir);
    cleanup.dir.clear();
  }
  if (!o.plot.empty()) write_text_file_atomic(o.plot, sequence_svg(r));
  const std::string revision = build_revision() + (o.shader_dir.empty() ? "" : " (shaders from " + o.shader_dir + ")");
  write_text_file_atomic(o.json, sequence_json({gi.renderer, gi.version, clock}, revision, r).dump(2) + "\n");
  std::printf("scene %s, path %s, %d frames at %.0f fps, %dx%d, truth every %d\n%s", r.scene.c_str(), r.path.c_str(),
              o.frames, o.fps, w, h, o.truth_every, sequence_table(r).c_str());
  for (const SequenceSummary& s : r.summary)
    if (s.nonfinite) return 1;
  return 0;
}

}  // namespace

Command add_sequence_command(CLI::App& app) {
  auto o = std::make_shared<SequenceOptions>();
  CLI::App* c = app.add_subcommand("sequence", "Render a camera path; score every frame and the flicker, ghosting and convergence.");
  c->add_option("--scene", o->scene, "Built-in scene name or a .json/.obj path.")->capture_default_str();
  c->add_option("--path", o->path, "The scene's camera path, or 'still' (default: the scene's path option or first path).");
  c->add_option("--frames", o->frames, "Frames to render (frame i at time i / fps).")->required();
  c->add_option("--techniques", o->techniques, "Comma-separated techniques (default: all but the reference).");
  c->add_option("--preset", o->presets, "Add a named preset as its own technique (repeatable).");
  c->add_option("--set", o->sets, "Parameter assignment technique.key=value (repeatable; reference.* too).");
  c->add_option("--sweep", o->sweeps,
                "technique.key=v1,v2,... (repeatable; sweeps of one technique multiply): each value its own technique.");
  c->add_option("--size", o->size, "Image size: WIDTHxHEIGHT or " + size_names() + ".")->capture_default_str();
  c->add_option("--truth-every", o->truth_every,
                "Truth at frames 0, K, 2K, ... and the frame after each (flicker needs pairs).")->capture_default_str();
  c->add_flag("--second-truth", o->second_truth,
              "Render each truth twice (another seed) for flicker's ratio without the truth's noise.");
  c->add_option("--fps", o->fps, "Frames per second of scene time, in [0.01, 1000].")->capture_default_str();
  add_frame_options(c, &o->frame);
  c->add_option("--json", o->json, "Results JSON (README: sequence JSON).")->required();
  c->add_option("--out", o->out, "A new (or empty) directory for the labelled PNG frames.");
  c->add_option("--video", o->video, "Side-by-side video (.mp4/.mkv; needs ffmpeg).");
  c->add_option("--plot", o->plot, "SVG: PSNR per frame and flicker per frame.");
  c->add_option("--gl", o->gl, "GL path: " + gl::backend_names() + ".")->capture_default_str();
  c->add_option("--shaders", o->shader_dir,
                "Load shaders from this directory instead of the embedded copy (to compare a variant's frames).");
  return {c, [o] { return run_sequence_command(*o); }};
}

}  // namespace ssr
