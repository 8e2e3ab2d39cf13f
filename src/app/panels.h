// ImGui panels drawn from the Params tables (the one description per parameter). No window
// code here, so the panels also run against ImGui's null backend in tests.
#pragma once
#include "techniques/params.h"

namespace ssr {

// One widget per parameter (slider with the table's range, checkbox, or combo), the help text
// as a tooltip, a reset button per parameter and a 'reset all' button. Returns true when a value changed.
bool draw_param_panel(ParamSet& params);

}  // namespace ssr
