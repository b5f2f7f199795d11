#pragma once

#include "apcs/formats/key_event.h"
#include "apcs/lesson/replay_driver.h"

#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// The pure part of `apcs grade EXERCISE.keys RECORDING...` (SPEC §3.1): which recordings are of
// the exercise, and the report's CSV rows made from what their replays reached. No files here:
// src/cli/grade_command.cpp reads the recordings and replays them.

// The `reached` column of a row: the goal held once its answer had played (yes) or not (no, also
// for a goal skipped, which a headless replay never does), a recording of another exercise
// (other: not replayed), or a recording that could not be read or parsed (error).
enum class GradeVerdict { yes, no, other, error };

// "yes", "no", "other", "error".
std::string_view verdict_name(GradeVerdict verdict);

// The names a row repeats, as the teacher typed them on the command line.
struct GradeNames {
    std::string recording;
    std::string exercise;
};

// One line of the report after its header.
struct GradeRow {
    std::string file;     // the recording, as named on the command line
    std::string exercise; // EXERCISE.keys, as named on the command line
    std::string goal;     // the goal's GOAL line as goal_line() writes it
    GradeVerdict reached = GradeVerdict::no;
    std::string value; // the goal's quantity when it was judged ("+0.45", "0.35"); empty for other, error
    std::string keys;  // the answer's keys as script tokens ("L L L 6", "= TEXT 0.45 ENTER")
    bool operator==(const GradeRow&) const = default;
};

// The report's first line, without its line end.
inline constexpr std::string_view grade_csv_header = "file,exercise,goal,reached,value,keys";

// A CSV field as RFC 4180 writes it: in double quotes, each quote doubled, when it holds a comma,
// a double quote, CR or LF; as it is otherwise. A field a spreadsheet would take for a formula
// (it begins with = + - @, a tab or CR and is not a number such as "+0.45"), and one that begins
// with an apostrophe already, begins with an apostrophe, so it is shown as the text it is: an answer's keys "= TEXT 0.45 ENTER" are not
// run, nor is a student's file named "=HYPERLINK(...).keys".
std::string csv_field(std::string_view text);

// A row as one CSV record ended by "\n" (LF: what Unix tools and spreadsheets read; a field that
// holds a line end is quoted, so records stay apart).
std::string grade_csv_line(const GradeRow& row);

// Whether `recording` is a recording of `exercise`: the same GOAL lines (kind, staff line, numbers,
// in order) and the same INPUT lines (name and checksum, in order). Where the lines stand in each
// file (line numbers, the keys around them) does not count: a recording holds the student's keys.
bool same_exercise(const KeyScript& exercise, const KeyScript& recording);

// The keys of goal `goal`'s answer in `script` (events [before_event, answer_end)), as script
// tokens separated by single spaces: a physical key by its script name (ENTER, LEFT, …), a
// printable character as itself, the keys of one TEXT line as "TEXT " and its text, a ';' typed
// alone as "TEXT ;". Empty when the goal has no answer (the exercise itself).
std::string answer_tokens(const KeyScript& script, const ScriptGoal& goal);

// The rows of a recording of the exercise that was replayed: one per goal of `recording`, in
// order, its verdict and value from `outcomes` (a goal with no outcome grades no, its value empty).
std::vector<GradeRow> replayed_rows(const GradeNames& names, const KeyScript& recording,
                                    const std::vector<GoalOutcome>& outcomes);

// The rows of a recording that was not replayed (GradeVerdict::other or ::error): one per goal of
// the exercise, value and keys empty.
std::vector<GradeRow> unreplayed_rows(const GradeNames& names, const KeyScript& exercise, GradeVerdict verdict);

} // namespace apcs
