#include "viewer/commands.h"

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "viewer/preset.h"
#include "core/cli_common.h"
#include "core/errors.h"
#include "core/files.h"
#include "render/renderer.h"
#include "techniques/technique.h"
#include "registry/presets.h"
#include "registry/registry.h"

namespace ssr {

namespace {

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

void check(ArgForm kind, const std::string& a, const std::string& at) {
  switch (kind) {
    case ArgForm::None:
    case ArgForm::Text: return;
    case ArgForm::Technique: create_technique(a); return;  // throws naming the known ones
    case ArgForm::Number: number(a, at); return;
    case ArgForm::NonNegative:
      if (number(a, at) < 0) throw InputError(at + "'" + a + "' must be >= 0.");
      return;
    case ArgForm::Fraction: {
      const double v = number(a, at);
      if (v < 0 || v > 1) throw InputError(at + "'" + a + "' must be in [0,1].");
      return;
    }
    case ArgForm::Count: {
      const double v = number(a, at);
      if (v < 1 || v > 100000 || v != std::floor(v))
        throw InputError(at + "'" + a + "' must be a whole number of frames in [1,100000].");
      return;
    }
    case ArgForm::Size: parse_size(a); return;
    case ArgForm::Compare: parse_compare_mode(a); return;
    case ArgForm::View: {
      const auto& names = viewer_view_names();
      if (std::find(names.begin(), names.end(), a) == names.end()) {
        std::string known;
        for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
        throw InputError(at + "unknown view '" + a + "' (known: " + known + ").");
      }
      return;
    }
    case ArgForm::Assignment: {
      const auto dot = a.find('.'), eq = a.find('=');
      if (dot == std::string::npos || eq == std::string::npos || dot > eq)
        throw InputError(at + "'" + a + "' is not of the form technique.key=value.");
      create_technique(a.substr(0, dot));
      return;
    }
    case ArgForm::OnOff:
      if (a != "on" && a != "off") throw InputError(at + "'" + a + "' is not on or off.");
      return;
    case ArgForm::TruthPolicy:
      if (a != "now" && a != "rest" && a != "live" && a != "manual")
        throw InputError(at + "'" + a + "' is not one of now, rest, live, manual.");
      return;
    case ArgForm::Section: {  // "NAME open|closed", joined like a pixel's
      const auto space = a.find(' ');
      parse_panel_section(a.substr(0, space));
      if (const std::string state = a.substr(space + 1); state != "open" && state != "closed")
        throw InputError(at + "'" + state + "' is not open or closed.");
      return;
    }
    case ArgForm::Pixel: {  // "X Y": parse_viewer_script joins the two words
      const auto space = a.find(' ');
      for (const std::string& v : {a.substr(0, space), a.substr(space + 1)}) {
        const double n = number(v, at);
        if (n < 0 || n != std::floor(n) || n > 65535) throw InputError(at + "'" + v + "' is not a pixel coordinate.");
      }
      return;
    }
    case ArgForm::Zoom: {
      if (a == "off") return;
      const double v = number(a, at);
      if (v < 2 || v > 16 || v != std::floor(v)) throw InputError(at + "zoom '" + a + "' must be off or a whole number in [2,16].");
      return;
    }
    case ArgForm::PresetName: find_preset(a); return;  // throws listing the names
    case ArgForm::Png: {
      if (files::lower_extension(a) != ".png")  // as ssrlab takes A.PNG
        throw InputError(at + "screenshot '" + a + "' must end in .png.");
      const std::filesystem::path dir = std::filesystem::absolute(a).parent_path();
      std::error_code ec;
      if (!std::filesystem::is_directory(dir, ec))
        throw InputError(at + "the directory '" + dir.string() + "' of screenshot '" + a + "' does not exist.");
      return;
    }
  }
}

}  // namespace

namespace {

// The entry of a named table (kCompareModes, kPanelSections) called `name`; an InputError
// listing the names otherwise ("compare mode 'x' is not one of off, split, ...").
template <class Entry, std::size_t N>
const Entry& named_entry(const Entry (&table)[N], const std::string& name, const std::string& what) {
  std::string known;
  for (const Entry& e : table) {
    if (name == e.name) return e;
    known += (known.empty() ? "" : ", ") + std::string(e.name);
  }
  throw InputError(what + " '" + name + "' is not one of " + known + ".");
}

}  // namespace

CompareMode parse_compare_mode(const std::string& name) { return named_entry(kCompareModes, name, "compare mode").mode; }

PanelSection parse_panel_section(const std::string& name) {
  return named_entry(kPanelSections, name, "panel section").section;
}

static_assert([] {
  for (std::size_t i = 0; i < kPanelSectionCount; ++i)
    if (static_cast<std::size_t>(kPanelSections[i].section) != i) return false;
  return true;
}(), "kPanelSections is in PanelSection order");

std::vector<std::string> compare_mode_names() {
  std::vector<std::string> names;
  for (const CompareInfo& c : kCompareModes) names.push_back(c.name);
  return names;
}

static_assert([] {
  for (std::size_t i = 0; i < std::size(kCompareModes); ++i)
    if (static_cast<std::size_t>(kCompareModes[i].mode) != i) return false;
  return true;
}(), "kCompareModes is in CompareMode order");

const CommandInfo& command_info(Verb verb) { return kCommands[static_cast<std::size_t>(verb)]; }

// The table is in Verb order (command_info indexes it).
static_assert([] {
  for (std::size_t i = 0; i < kCommandCount; ++i)
    if (static_cast<std::size_t>(kCommands[i].verb) != i) return false;
  return true;
}());

std::string commands_markdown() {
  std::string out = "| command | what it does |\n|---|---|\n";
  for (const CommandInfo& c : kCommands) {
    std::string help = c.help;
    // A form whose names come from a table: listed from it, not in the help text.
    std::vector<std::string> names;
    if (c.form == ArgForm::Compare) names = compare_mode_names();
    if (c.form == ArgForm::Section)
      for (const SectionInfo& s : kPanelSections) names.push_back(s.name);
    for (std::size_t i = 0; i < names.size(); ++i) help += (i ? ", " : " ") + names[i];
    out += "| `" + markdown_cell(std::string(c.name) + (*c.args ? " " : "") + c.args) + "` | " + markdown_cell(help) + " |\n";
  }
  return out;
}

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
    std::string verb;
    if (!(words >> verb)) continue;
    for (std::string w; words >> w;) c.args.push_back(w);
    const std::string at = script_where(where, c);
    const auto v = std::find_if(std::begin(kCommands), std::end(kCommands),
                                [&](const CommandInfo& k) { return verb == k.name; });
    if (v == std::end(kCommands)) throw InputError(at + "unknown command '" + verb + "'.");
    c.verb = v->verb;
    const std::size_t want = v->form == ArgForm::None ? 0 : v->form == ArgForm::Pixel || v->form == ArgForm::Section ? 2 : 1;
    if (c.args.size() != want)
      throw InputError(at + "'" + verb + "' takes " + (want == 0 ? "no argument" : want == 1 ? "one argument" : "two arguments") +
                       ", not " + std::to_string(c.args.size()) + ".");
    if (want == 2) c.args = {c.args[0] + " " + c.args[1]};  // one argument for the handler
    try {
      if (want) check(v->form, c.args[0], at);
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
