// ssrlab-view: the interactive viewer (GLFW window + Dear ImGui). The command line; the session
// is viewer.h's Viewer.
//
//   mouse: left drag orbits around the target, right drag pans, wheel zooms
//   WASD/QE: fly (Shift x4, Ctrl x0.25)   F1: keys   F2: side panel   F5: reload shaders   F12: screenshot
//   Compare: technique A alone, A | B with a draggable divider, or |A - B| as a heat map with the
//   PSNR. The reference (CPU ray tracing) runs once the camera rests, or when asked.
//   --frames N --screenshot F.png, or --script FILE (commands.h): scripted runs for tests.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "core/cli_common.h"
#include "core/cli_options.h"
#include "core/errors.h"
#include "viewer/viewer.h"

int main(int argc, char** argv) {
  using namespace ssr;
  CLI::App app{"ssrlab-view: interactive screen-space reflection viewer"};
  ViewerOptions o;
  bool help_script = false;
  app.add_option("--scene", o.scene, "Built-in scene name (with options, e.g. gallery:reflectors=5) or a .json/.obj path.")->capture_default_str();
  app.add_option("--technique", o.technique, "Technique A (the left of a split).")->capture_default_str();
  app.add_option("--set", o.sets, "Parameter assignment technique.key=value (repeatable).");
  app.add_option("--size", o.size, "Image size: WIDTHxHEIGHT or " + size_names() + " (the window adds the side panel and the status bar).")->capture_default_str();
  app.add_option("--camera", o.camera, "Named camera of the scene.");
  app.add_option("--view", o.view, "Initial view (final, reflection, confidence, lit, ..., traceable).")->capture_default_str();
  app.add_option("--frames", o.frames, "Render this many frames, then exit (0: interactive).")->check(CLI::Range(0, 100000));
  app.add_option("--screenshot", o.screenshot, "With --frames: write the last frame's image to this PNG.");
  app.add_option("--shaders", o.shader_dir, "Shader directory for live reload (F5).");
  app.add_option("--technique-b", o.technique_b, "Technique B (right of the split, or diffed against A).")->capture_default_str();
  app.add_option("--split", o.split, "Start in split view with the divider at X (0..1 of the width).")->check(CLI::Range(0.0, 1.0));
  app.add_flag("--diff", o.diff, "Start in difference mode: a heat map of |A - B| and the PSNR.");
  app.add_flag("--no-panel", o.no_panel, "Start with the side panel hidden (F2 shows it).");
  app.add_option("--preset", o.preset, "Start from a JSON preset saved by the viewer.");
  app.add_option("--script", o.script, "Run the commands of this file (--help-script lists them), then exit.");
  app.add_flag("--help-script", help_script, "List the script commands and exit.");
  app.add_option("--ini", o.ini, "ImGui layout file (default: ~/.config/ssrlab/imgui.ini).");
  refuse_empty_values(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "ssrlab-view: %s.\n", parse_error_sentence(app, "ssrlab-view", argc, argv, e).c_str());
    return 2;
  }
  if (help_script) {
    std::printf("%s", commands_markdown().c_str());
    return 0;
  }
  try {
    return Viewer(o).run();
  } catch (const InputError& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ssrlab-view: %s\n", e.what());
    return 1;
  }
}
