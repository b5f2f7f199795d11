#pragma once

#include "apcs/animation/motion_path.h"
#include "apcs/base/diagnostic.h"
#include "apcs/session/exit_status.h"

#include <iosfwd>

namespace apcs {

// Writes "FILE:LINE: message" on its own line to `err`; the exit status of bad input.
ExitStatus report_bad_input(const Diagnostic& problem, std::ostream& err);

// "apcs: M in-betweens from N curve samples: frames will freeze" when the path has fewer samples
// than in-betweens asked for (SPEC §4.3).
void warn_if_frames_freeze(const EvaluatedPath& path, int inbetween_count, std::ostream& err);

} // namespace apcs
