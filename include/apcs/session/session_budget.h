#pragma once

#include "apcs/session/session.h"

#include <cstddef>
#include <optional>
#include <string>

namespace apcs {

// The session's checks against the memory budget (memory_budget.h), made at the step where a
// request becomes known; the refusal is that step's message, and the step is asked again.

// After KEY2: surface fitting will hold M + 2 frames of the larger key's points.
std::optional<std::string> frames_refusal(std::size_t key_points, const SessionSettings& settings);

// After a path file: its curve is sampled at --samples per segment for the path editor.
std::optional<std::string> path_refusal(std::size_t control_points, const SessionSettings& settings);

} // namespace apcs
