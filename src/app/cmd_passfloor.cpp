// `ssrlab passfloor`: the pass-floor microbenchmark (eval/pass_floor.h). What one full-screen
// pass costs on this device, by how it is issued (compute group shapes, fragment) and by its
// work (none to a 5x5 box of fetches), alone and in chains: what a pass's launches cost against
// what its work costs (docs/RESULTS.md, "What one screen pass costs").
#include <cstdio>
#include <regex>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "gl/context.h"
#include "core/revision.h"
#include "eval/pass_floor.h"
#include "eval/results.h"
#include "registry/variants.h"

namespace ssr {
namespace {

struct PassFloorOptions {
  std::string sizes = "1080p,4k";
  std::string modes = "all", kinds = "all";
  std::string chains = "1,6,24";
  int frames = 30;
  std::string json;
  std::string gl = "auto";
};

// Entries per list (sizes, modes, kinds, chains): every case takes at least 0.3 s of warm-up.
constexpr std::size_t kMaxPassFloorList = 16;

std::vector<std::string> bounded_list(const std::string& text, const char* what) {
  std::vector<std::string> items = split_list(text, what);
  if (items.size() > kMaxPassFloorList)
    throw InputError(std::to_string(items.size()) + " " + what + "s given, at most " +
                     std::to_string(kMaxPassFloorList) + " supported.");
  return items;
}

template <class T>
std::vector<const T*> pick(const std::string& list, std::span<const T> all, const T& (*by_name)(const std::string&),
                           const char* what) {
  std::vector<const T*> out;
  if (list == "all") {
    for (const T& e : all) out.push_back(&e);
    return out;
  }
  for (const std::string& name : bounded_list(list, what)) out.push_back(&by_name(name));
  return out;
}

int run_passfloor(const PassFloorOptions& o) {
  std::vector<std::pair<int, int>> sizes;
  for (const std::string& s : bounded_list(o.sizes, "size")) sizes.push_back(parse_size(s));
  const auto modes = pick<PassFloorMode>(o.modes, pass_floor_modes(), pass_floor_mode, "pass mode");
  const auto kinds = pick<PassFloorKind>(o.kinds, pass_floor_kinds(), pass_floor_kind, "pass kind");
  std::vector<int> chains;
  static const std::regex whole(R"(^[0-9]{1,3}$)");
  for (const std::string& c : bounded_list(o.chains, "chain length")) {
    const int n = std::regex_match(c, whole) ? std::stoi(c) : 0;
    if (n < 1 || n > 256) throw InputError("chain length '" + c + "' is not a whole number from 1 to 256.");
    chains.push_back(n);
  }
  if (o.frames < 1 || o.frames > 10000) throw InputError("--frames must be in [1, 10000].");
  require_output_files({{"--json", o.json}});

  auto ctx = open_gl(o.gl, sizes);
  const gl::ContextInfo& gi = ctx->info();
  const std::string clock = gi.software ? "cpu" : "gpu";
  const auto timer_clock = gi.software ? gl::PassTimer::Clock::Cpu : gl::PassTimer::Clock::Gpu;
  nlohmann::json rows = nlohmann::json::array();
  std::printf("| size | mode | kind | passes | ms | ms a pass |\n|---|---|---|---|---|---|\n");
  for (auto [w, h] : sizes) {
    PassFloorBench bench(gl::ShaderSource(), w, h);
    for (const PassFloorMode* m : modes)
      for (const PassFloorKind* k : kinds)
        for (int chain : chains) {
          const double ms = bench.time_ms(*m, *k, chain, o.frames, timer_clock);
          std::printf("| %dx%d | %s | %s | %d | %.4f | %.4f |\n", w, h, m->name, k->name, chain, ms, ms / chain);
          std::fflush(stdout);
          rows.push_back({{"size", std::to_string(w) + "x" + std::to_string(h)}, {"mode", m->name},
                          {"kind", k->name}, {"chain", chain}, {"ms", ms}, {"ms_per_pass", ms / chain}});
        }
  }
  nlohmann::json legend;
  for (const PassFloorMode& m : pass_floor_modes()) legend["modes"][m.name] = m.description;
  for (const PassFloorKind& k : pass_floor_kinds()) legend["kinds"][k.name] = k.description;
  nlohmann::json device = device_json({gi.renderer, gi.version, clock});
  device["timing"] = gi.software ? "a chain of passes: CPU clock around glFinish"
                                 : "a chain of passes: two GL_TIMESTAMP queries, none between its passes";
  if (!o.json.empty())
    write_text_file_atomic(o.json, nlohmann::json{{"device", device},
                                                   {"revision", build_revision()},
                                                   {"frames", o.frames},
                                                   {"legend", legend},
                                                   {"results", rows}}
                                           .dump(2) + "\n");
  std::printf("device: %s | %s | clock %s | revision %s\n", gi.renderer.c_str(), gi.version.c_str(), clock.c_str(),
              build_revision());
  return 0;
}

}  // namespace

Command add_passfloor_command(CLI::App& app) {
  auto o = std::make_shared<PassFloorOptions>();
  CLI::App* c = app.add_subcommand(
      "passfloor", "Time what one full-screen pass costs by itself: compute group shapes and fragment passes, "
                   "from no work to a 5x5 box of fetches, alone and in chains.");
  c->add_option("--sizes", o->sizes, "Comma-separated sizes: WxH or " + size_names() + ".")->capture_default_str();
  c->add_option("--modes", o->modes, "Comma-separated: " + pass_floor_mode_names() + " (or all).")->capture_default_str();
  c->add_option("--kinds", o->kinds, "Comma-separated: " + pass_floor_kind_names() + " (or all).")->capture_default_str();
  c->add_option("--chains", o->chains, "Comma-separated numbers of passes in a row per timed span (1-256).")
      ->capture_default_str();
  c->add_option("--frames", o->frames, "Timed frames per case (after 10 and at least 0.3 s of warm-up).")
      ->capture_default_str();
  c->add_option("--json", o->json, "Results JSON.");
  c->add_option("--gl", o->gl, "GL path: " + gl::backend_names() + ".")->capture_default_str();
  return {c, [o] { return run_passfloor(*o); }};
}

}  // namespace ssr
