// The subcommands of `ssrlab` (ARCHITECTURE §7). Each validates all input before touching the GL and
// throws InputError (exit 2) or RuntimeError (exit 1).
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "gl/context.h"

namespace CLI { class App; }

namespace ssr {

// Opens the headless context, checks every frame size against the GL's limit (InputError), then
// logs the path taken and GL_RENDERER on stderr: bad input still gets exactly one line there.
std::unique_ptr<gl::HeadlessContext> open_gl(const std::string& path,
                                             const std::vector<std::pair<int, int>>& sizes);

struct FrameSettings;

// The frame settings a user sets (frame_settings_table: exposure, reflective_f0) as options of
// each command that renders, one per row of the table, named after it: --exposure,
// --reflective-f0 (`--set frame.*` is not a technique's parameter).
struct FrameOptions {
  std::vector<std::optional<double>> values;  // per table row; none: its default
};
void add_frame_options(CLI::App* command, FrameOptions* o);
// Checked against the table's ranges, naming the option (InputError), before any GL work.
FrameSettings frame_settings(const FrameOptions& o);

// Registers the subcommand on `app`; the returned function runs it after parsing.
struct Command {
  CLI::App* sub;
  std::function<int()> run;
};
Command add_render_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_sequence_command(CLI::App& app);
Command add_passfloor_command(CLI::App& app);

}  // namespace ssr
