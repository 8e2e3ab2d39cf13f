// "technique.key=value" assignments (the CLI's --set, presets, scripts) applied to a technique.
#pragma once
#include <string>
#include <vector>

#include "render/technique_api.h"

namespace ssr {

// Applies "key=value" assignments to a technique's parameters; unknown keys, keys of another
// technique and bad values throw InputError.
void apply_assignments(Technique& technique, const std::vector<std::string>& assignments);

}  // namespace ssr
