#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/lesson/grade.h"

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <vector>

namespace apcs {

// What `apcs grade EXERCISE.keys RECORDING...` was given, as typed (SPEC §3.1).
struct GradeRequest {
    std::filesystem::path exercise;
    std::vector<std::filesystem::path> recordings;
    // The operations a replay may cost (lesson/grade.h); not an option: tests make it small.
    std::uint64_t work_budget = most_replay_operations;
};

// What `apcs grade --class DIR EXERCISE.keys…` was given (SPEC §3.2).
struct GradeClassRequest {
    std::filesystem::path class_folder; // one folder a student, each recording named as its exercise
    std::vector<std::filesystem::path> exercises;
    std::optional<std::filesystem::path> feedback; // --feedback DIR2: DIR2/STUDENT.txt for each
    std::uint64_t work_budget = most_replay_operations;
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
// Recordings are graded on every core, as many replays at once as the memory allows (SPEC §3.2:
// under 100 MB in all, or APCS_MEMORY_LIMIT when lower; lesson/grade.h's figures); the rows are
// printed in the order given, each recording's as soon as it and those before it are graded. A
// replay whose keys cost more than most_replay_operations, or that would need more memory than the
// run has for replays, is an error row, "too long".
ExitStatus run_grade_command(const GradeRequest& request, const CommonOptions& options, std::ostream& out,
                             std::ostream& err);

// `apcs grade --class`: every student folder of DIR (each folder in it, sorted by name; hidden ones
// left out) graded against every exercise as run_grade_command grades one recording, its recording
// being DIR/STUDENT/EXERCISE's file name; the gradebook on `out` (lesson/gradebook.h: a row per
// student, cells yes, no, other, error or missing, the goals reached, of how many, same_as), once
// all are graded. With `feedback`, DIR2/STUDENT.txt for each (the folder made if missing; an
// earlier file kept as .bak). Exit 0 when every recording handed in was graded (missing ones
// included), 1 when one was an error or a feedback file could not be written, 2 for an
// APCS_MEMORY_LIMIT that is no byte count.
ExitStatus run_grade_class_command(const GradeClassRequest& request, const CommonOptions& options, std::ostream& out,
                                   std::ostream& err);

} // namespace apcs
