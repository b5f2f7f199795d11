#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"

#include <filesystem>
#include <iosfwd>
#include <vector>

namespace apcs {

// What `apcs grade EXERCISE.keys RECORDING...` was given, as typed (SPEC §3.1).
struct GradeRequest {
    std::filesystem::path exercise;
    std::vector<std::filesystem::path> recordings;
};

// `apcs grade`: each recording replayed headless, as `apcs --keys RECORDING --workdir COPY
// </dev/null` replays it, on a fresh copy of the exercise's inputs, and the CSV report on `out`
// (lesson/grade.h): the header, then one row per recording and goal.
//
// The inputs are the exercise's INPUT files beside EXERCISE.keys, checked against their CRC-32
// first: one missing or changed (or a link, a FIFO), an exercise that cannot be read or names no
// GOAL or no INPUT, is exit 1 with FILE:LINE on `err` and nothing on `out`. They are copied once
// into a private folder (mkdtemp, mode 0700, under TMPDIR or /tmp), and from there into a fresh
// work folder for each recording; both are removed at the end, also after an error or a stop by
// a signal. Nothing is written beside the exercise or a recording: the sessions write in the
// copies.
//
// A recording is read as `--keys` reads a file, except that only a regular file (or a symbolic
// link to one, followed: it is only read) is read, so a FIFO nobody writes never hangs the
// report; a directory, a device, a missing file or a script that does not parse is an `error` row
// per goal of the exercise, the reason (FILE:LINE) on `err`. A recording whose GOAL or INPUT lines
// differ from the exercise's, or whose OPTIONS set another task (script_options.h), is an `other`
// row per goal, not replayed; else it is replayed with its OPTIONS. The replays' screens and
// messages are not shown. Exit 0 when every recording was graded (yes, no or other), 1 when one was
// an error, 2 for an APCS_MEMORY_LIMIT that is no byte count.
ExitStatus run_grade_command(const GradeRequest& request, const CommonOptions& options, std::ostream& out,
                             std::ostream& err);

} // namespace apcs
