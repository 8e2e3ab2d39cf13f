// CLI11 rules that both programs' command lines follow (header-only: only src/app and
// src/viewer, which link CLI11, include it).
#pragma once
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>

#include <CLI/CLI.hpp>

namespace ssr {

// Every option of `app` and of its subcommands that takes a value refuses an empty one: CLI11
// reads `--warmup ""` as 0 and `--json ""` as "not given", so a value lost to shell quoting
// would run silently with another meaning. Call after the options are added, before parse.
inline void refuse_empty_values(CLI::App& app) {
  const CLI::Validator non_empty(
      [](std::string& value) { return value.empty() ? std::string("needs a value, not an empty string") : std::string(); },
      "");
  for (CLI::Option* o : app.get_options())
    if (o->get_type_size() != 0 && !o->get_positional()) o->check(non_empty);
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) refuse_empty_values(*sub);
}

// CLI11's parse error as one clear sentence (no final full stop), reworded where CLI11's is not
// one. `program`: "ssrlab" or "ssrlab-view", for the --help hint.
inline std::string parse_error_sentence(const CLI::App& app, const std::string& program, int argc, char** argv,
                                        const CLI::ParseError& e) {
  std::string known;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    known += (known.empty() ? "" : ", ") + sub->get_name();
  if (!known.empty() && argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty())
    return "unknown subcommand '" + std::string(argv[1]) + "' (known: " + known + ")";
  const std::string what = e.what();
  std::smatch m;
  static const std::regex conversion(R"(^Could not convert: (\S+) = (.*)$)");
  static const std::regex extras(R"(^The following arguments? (?:was|were) not expected: (.*)$)");
  static const std::regex missing(R"(^(\S+): \d+ required \S+ missing$)");
  static const std::regex twice(R"(^(\S+): At Most 1 required but received \d+$)");
  static const std::regex empty(R"(^(\S+): needs a value, not an empty string$)");
  static const std::regex range(R"(^(\S+): Value (\S+) not in range (\S+) to (\S+)$)");
  if (std::regex_match(what, m, conversion))
    return "option " + m[1].str() + " cannot take the value '" + m[2].str() + "' (wrong type, or out of range)";
  if (std::regex_match(what, m, extras)) {
    // The message lists them last first; the parse kept them in the order given.
    std::string given;
    for (const std::string& a : app.remaining(/*recurse=*/true)) given += (given.empty() ? "" : " ") + a;
    return "unknown option or unexpected argument '" + (given.empty() ? m[1].str() : given) + "' (see " + program + " " +
           (app.get_subcommands().empty() ? "" : app.get_subcommands().front()->get_name() + " ") + "--help)";
  }
  if (std::regex_match(what, m, missing)) return "option " + m[1].str() + " needs a value";
  if (std::regex_match(what, m, twice)) return "option " + m[1].str() + " is given more than once";
  if (std::regex_match(what, m, range)) {
    const auto num = [](const std::string& t) {  // CLI11 writes 0.000000
      char b[32];
      std::snprintf(b, sizeof b, "%g", std::strtod(t.c_str(), nullptr));
      return std::string(b);
    };
    return "option " + m[1].str() + " must be in [" + num(m[3].str()) + ", " + num(m[4].str()) + "], got " + m[2].str();
  }
  if (std::regex_match(what, m, empty)) return "option " + m[1].str() + " needs a value, not an empty string";
  if (what == "A subcommand is required") return "a subcommand is required (one of " + known + ")";
  return what;
}

}  // namespace ssr
