// What `stochastic` reports about its last frame, for tests and the speed report.
#pragma once
#include "shared/classification.h"
#include "techniques/technique.h"

namespace ssr {

// The tile list's header after the last frame of a `stochastic` technique: tiles listed (the
// indirect dispatch's work groups) and rays the trace cast. Reads back from the GL (stalls).
// Throws std::bad_cast for any other technique.
shared::TileListHeader stochastic_tile_counts(const Technique& stochastic);

}  // namespace ssr
