#include "app/viewer_script.h"

#include <algorithm>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "app/viewer_preset.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "render/renderer.h"
#include "techniques/technique.h"
#include "registry/registry.h"

namespace ssr {

namespace {

enum class Arg { None, Text, Technique, Number, NonNegative, Fraction, Count, Size, Compare, View, Assignment, Png };

// verb -> the form of its one argument (Arg::None: no argument).
const std::map<std::string, Arg>& verbs() {
  static const std::map<std::string, Arg> v = {
      {"scene", Arg::Text},       {"camera", Arg::Text},        {"technique", Arg::Technique},
      {"technique-b", Arg::Technique}, {"set", Arg::Assignment}, {"compare", Arg::Compare},
      {"split", Arg::Fraction},   {"view", Arg::View},          {"exposure", Arg::Number},
      {"ambient", Arg::NonNegative}, {"frames", Arg::Count},    {"screenshot", Arg::Png},
      {"preset-save", Arg::Text}, {"preset-load", Arg::Text},   {"resize", Arg::Size},
      {"minimise", Arg::None},    {"restore", Arg::None},       {"reload", Arg::None},
      {"path", Arg::Text},        {"time", Arg::NonNegative},   {"play", Arg::None},
      {"pause", Arg::None},
  };
  return v;
}

double number(const std::string& s, const std::string& at) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || !std::isfinite(v)) throw InputError(at + "'" + s + "' is not a finite number.");
  return v;
}

void check(Arg kind, const std::string& a, const std::string& at) {
  switch (kind) {
    case Arg::None:
    case Arg::Text: return;
    case Arg::Technique: create_technique(a); return;  // throws naming the known ones
    case Arg::Number: number(a, at); return;
    case Arg::NonNegative:
      if (number(a, at) < 0) throw InputError(at + "'" + a + "' must be >= 0.");
      return;
    case Arg::Fraction: {
      const double v = number(a, at);
      if (v < 0 || v > 1) throw InputError(at + "'" + a + "' must be in [0,1].");
      return;
    }
    case Arg::Count: {
      const double v = number(a, at);
      if (v < 1 || v > 100000 || v != std::floor(v))
        throw InputError(at + "'" + a + "' must be a whole number of frames in [1,100000].");
      return;
    }
    case Arg::Size: parse_size(a); return;
    case Arg::Compare:
      if (a != "off" && a != "split" && a != "diff")
        throw InputError(at + "compare mode '" + a + "' is not one of off, split, diff.");
      return;
    case Arg::View: {
      const auto& names = viewer_view_names();
      if (std::find(names.begin(), names.end(), a) == names.end()) {
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        throw InputError(at + "unknown view '" + a + "' (known: " + known + ").");
      }
      return;
    }
    case Arg::Assignment: {
      const auto dot = a.find('.'), eq = a.find('=');
      if (dot == std::string::npos || eq == std::string::npos || dot > eq)
        throw InputError(at + "'" + a + "' is not of the form technique.key=value.");
      create_technique(a.substr(0, dot));
      return;
    }
    case Arg::Png:
      if (std::filesystem::path(a).extension() != ".png")
        throw InputError(at + "screenshot '" + a + "' must end in .png.");
      return;
  }
}

}  // namespace

std::string script_where(const std::string& file, const ScriptCommand& c) {
  return file + ":" + std::to_string(c.line) + ": ";
}

std::vector<ScriptCommand> parse_viewer_script(const std::string& text, const std::string& where) {
  std::vector<ScriptCommand> out;
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    ScriptCommand c;
    c.line = n;
    if (!(words >> c.verb)) continue;
    for (std::string w; words >> w;) c.args.push_back(w);
    const std::string at = script_where(where, c);
    const auto v = verbs().find(c.verb);
    if (v == verbs().end()) throw InputError(at + "unknown command '" + c.verb + "'.");
    const std::size_t want = v->second == Arg::None ? 0 : 1;
    if (c.args.size() != want)
      throw InputError(at + "'" + c.verb + "' takes " + (want ? "one argument" : "no argument") + ", not " +
                       std::to_string(c.args.size()) + ".");
    try {
      if (want) check(v->second, c.args[0], at);
    } catch (const InputError& e) {
      const std::string msg = e.what();
      throw InputError(msg.rfind(where, 0) == 0 ? msg : at + msg);
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<ScriptCommand> load_viewer_script(const std::filesystem::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f || std::filesystem::is_directory(path))
    throw InputError("script '" + path.string() + "' cannot be read.");
  std::ostringstream text;
  text << f.rdbuf();
  return parse_viewer_script(text.str(), path.string());
}

}  // namespace ssr
