// Markdown tables of techniques, parameters, scenes and views, generated from the code's own
// tables (the README and docs/PARAMETERS.md hold them; tests/cli/docs_tables.sh compares).
#pragma once
#include <string>

namespace ssr {

std::string techniques_markdown();  // README "Techniques": name, description, own parameters
std::string parameters_markdown();  // docs/PARAMETERS.md: every parameter and preset
std::string scenes_markdown();      // README "Scenes": built-in scenes, their options and paths
std::string views_markdown();       // README: every view, its legend, who offers it

}  // namespace ssr
