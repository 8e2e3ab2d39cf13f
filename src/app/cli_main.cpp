// ssrlab: the headless command line (ARCHITECTURE §7). Exit codes: 0 ok, 1 runtime failure, 2 bad input.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "app/docs.h"
#include "core/cli_options.h"
#include "core/errors.h"
#include "scene/builtin_scenes.h"
#include "registry/presets.h"
#include "techniques/technique.h"
#include "registry/registry.h"

namespace fs = std::filesystem;
using namespace ssr;

namespace {

int list_scenes() {
  std::printf("built-in scenes:\n");
  for (const auto& s : builtin_scenes()) std::printf("  %-18s %s\n", s.name.c_str(), s.description.c_str());
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

int list_techniques() {
  // Columns as wide as their longest entry over every technique (keys such as
  // linear-binary.backface_thickness and ranges such as none|4-neighbour|8-neighbour are long).
  int key_w = 0, default_w = 0, range_w = 0;
  for (const TechniqueInfo& info : technique_registry()) {
    auto t = info.create();
    ParamSet p = t->params();
    for (std::size_t i = 0; i < p.size(); ++i) {
      key_w = std::max(key_w, static_cast<int>(p.key(i).size()));
      default_w = std::max(default_w, static_cast<int>(p.default_string(i).size()));
      range_w = std::max(range_w, static_cast<int>(p.range_string(i).size()));
    }
  }
  for (const TechniqueInfo& info : technique_registry()) {
    auto t = info.create();
    ParamSet p = t->params();
    std::printf("%s\n  %s\n", info.name.c_str(), info.description.c_str());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const ParamDesc& d = p.table()[i];
      std::printf("  %-*s default %-*s range %-*s %s%s%s%s\n", key_w, p.key(i).c_str(), default_w,
                  p.default_string(i).c_str(), range_w, p.range_string(i).c_str(), d.help,
                  *d.unit ? " (" : "", d.unit, *d.unit ? ")" : "");
    }
  }
  std::printf("presets (--preset NAME)\n");
  for (const Preset& p : presets()) {
    std::string sets;
    for (const auto& a : p.assignments) sets += " " + a;
    std::printf("  %-18s %s:%s\n  %-18s %s\n", p.name.c_str(), p.technique.c_str(), sets.c_str(), "",
                p.source.c_str());
  }
  return 0;
}

// Bad input: one sentence on stderr (ARCHITECTURE §7), line breaks folded, one final full stop.
int input_error(std::string msg) {
  for (char& c : msg)
    if (c == '\n' || c == '\r' || c == '\t') c = ' ';
  while (!msg.empty() && (msg.back() == ' ' || msg.back() == '.')) msg.pop_back();
  std::fprintf(stderr, "ssrlab: %s.\n", msg.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ssrlab: screen-space reflection laboratory (headless)"};
  app.require_subcommand(1);
  std::vector<Command> commands = {add_render_command(app), add_compare_command(app),
                                   add_bench_command(app), add_sequence_command(app),
                                   add_passfloor_command(app)};
  CLI::App* scenes = app.add_subcommand("scenes", "List the built-in scenes and scene files.");
  bool scenes_md = false;
  scenes->add_flag("--markdown", scenes_md, "The README's scene table instead.");
  CLI::App* techniques = app.add_subcommand("techniques", "List every technique with every parameter, and the presets.");
  std::string techniques_md;
  techniques->add_option("--markdown", techniques_md, "The README's technique table (summary) or docs/PARAMETERS.md (parameters).")
      ->check(CLI::IsMember({"summary", "parameters"}))
      ->expected(0, 1)
      ->default_str("summary");
  CLI::App* views = app.add_subcommand("views", "List the views (--view): what each shows, its legend, who offers it.");
  bool views_md = false;
  views->add_flag("--markdown", views_md, "Accepted as scenes and techniques take it: the listing is the README's Markdown table either way.");

  refuse_empty_values(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return input_error(parse_error_sentence(app, "ssrlab", argc, argv, e));
  }

  try {
    for (const Command& c : commands)
      if (c.sub->parsed()) return c.run();
    if (scenes->parsed()) return scenes_md ? (std::printf("%s", scenes_markdown().c_str()), 0) : list_scenes();
    if (techniques->parsed()) {
      if (techniques->count("--markdown") == 0) return list_techniques();
      std::printf("%s", (techniques_md == "parameters" ? parameters_markdown() : techniques_markdown()).c_str());
      return 0;
    }
    if (views->parsed()) {
      std::printf("%s", views_markdown().c_str());  // Markdown reads as plain text too
      return 0;
    }
  } catch (const InputError& e) {
    return input_error(e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ssrlab: %s\n", e.what());
    return 1;
  }
  return 0;
}
