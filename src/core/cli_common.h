// Pieces shared by the two programs' command lines.
#pragma once
#include <string>
#include <vector>

#include "techniques/technique.h"

namespace ssr {

// "WxH" -> {W, H}; throws InputError for anything else (0 sides included).
std::pair<int, int> parse_size(const std::string& text);

// Applies "key=value" assignments to a technique's parameters; unknown keys, keys of another
// technique and bad values throw InputError.
void apply_assignments(Technique& technique, const std::vector<std::string>& assignments);

}  // namespace ssr
