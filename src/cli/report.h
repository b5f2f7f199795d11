#pragma once

#include "apcs/animation/motion_path.h"
#include "apcs/base/diagnostic.h"
#include "apcs/base/exit_status.h"

#include <iosfwd>
#include <string>

namespace apcs {

// Writes "FILE:LINE: message" on its own line to `err`; the exit status of bad input.
ExitStatus report_bad_input(const Diagnostic& problem, std::ostream& err);

// "apcs: FILE: frames will freeze at KEY1=1, 5=6" ("=" joins two consecutive frames at one point,
// SPEC §4.3); with more in-betweens than curve samples it says so too.
void warn_if_frames_freeze(const EvaluatedPath& path, const std::string& file, std::ostream& err);

} // namespace apcs
