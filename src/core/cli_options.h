// CLI11 rules that both programs' command lines follow (header-only: only src/app and
// src/viewer, which link CLI11, include it).
#pragma once
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

}  // namespace ssr
