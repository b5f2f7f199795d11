#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/session/session_settings.h"

#include <cstddef>

namespace apcs {

// The session's checks against the memory budget (memory_budget.h), made at the step where a
// request becomes known; the diagnostic's message is that step's refusal, and the step is asked
// again.

// After KEY2: surface fitting will hold M + 2 frames of the larger key's points.
[[nodiscard]] Expected<void> check_frames_fit(std::size_t key_points, const SessionSettings& settings);

// After a path file: its curve is sampled at --samples per segment for the path editor.
[[nodiscard]] Expected<void> check_path_fits(std::size_t control_points, const SessionSettings& settings);

} // namespace apcs
