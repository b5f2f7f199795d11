#pragma once

#include "apcs/session/session_steps.h"

#include <optional>

namespace apcs {

// The step that follows `from` when it ended with `outcome`, made from it (session_graph.cpp's
// table), `from` possibly left moved from; nullopt, `from` untouched, where the table has no row.
std::optional<Step> next_step(Step& from, StepOutcome outcome, StepContext& context);

} // namespace apcs
