#pragma once

#include "apcs/formats/key_script.h"
#include "apcs/lesson/replay_driver.h"

#include <cstdint>
#include <optional>
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
    std::string keys;  // the answer's keys as script tokens ("L L L 6", "= TEXT 0.45 ENTER"), answer_field
    std::string options; // the recording's OPTIONS words where they differ from the exercise's
    // Not columns of the CSV; the words of a student's feedback (--feedback): the goal as it was
    // wanted ("tension within +0.40 to +0.60", goal_text) and, when it was judged, what the
    // student's path showed ("tension +0.50").
    std::string wanted;
    std::string said;
    bool operator==(const GradeRow&) const = default;
};

// The report's first line, without its line end.
inline constexpr std::string_view grade_csv_header = "file,exercise,goal,reached,value,keys,options";

// The most characters of keys a row shows (SPEC §3.2): a longer answer is cut there and ends
// "… (N keys)", so that a 100,000-key answer stays a field every CSV reader takes.
inline constexpr std::size_t most_answer_characters = 200;

// The most keys a recording may hold (SPEC §3.2): a longer one is an error row, "too long".
inline constexpr std::size_t most_recording_keys = 100'000;
// The largest recording read, in bytes: 100,000 keys of the longest name (BACKSPACE) with room
// for comments; a larger file is an error row before it is parsed, so its keys never take memory.
inline constexpr std::uintmax_t most_recording_bytes = std::uintmax_t{4} << 20;

// The work a replay may cost, in the operations of Session::key_work (SPEC §3.2): a key counts
// one, and one more for each control point of the largest path the session holds (a waypoint edit
// two of the curve's blocks and a 64th of the points). 1.2·10^7 is at most about 7 s of one replay
// on a 2-core machine where an operation costs most (staff keys on a path of 1,000 to 3,000
// control points: 0.5 µs each); 16,000 points inserted on way1.dat cost 7.7·10^6 (0.2 s); past it
// a recording is an error row, "too long", whatever the machine: the same verdict on every one.
inline constexpr std::uint64_t most_replay_operations = 12'000'000;

// Memory (SPEC §3.2: under 100 MB in all). apcs grade keeps grade_own_bytes for itself (the
// program, the exercises' copies, the recordings being read) and replays at once as many recordings
// as the rest holds, each counted at replay_bytes of its keys; APCS_MEMORY_LIMIT, when lower than
// most_grade_bytes, is the whole instead.
inline constexpr std::uint64_t most_grade_bytes = 100'000'000;
inline constexpr std::uint64_t grade_own_bytes = std::uint64_t{24} << 20;
// A replay's session, its paths (at most about 10^4 control points within the work budget) and
// its screens' state, then each key: the script and its copy with the answers moved (24 bytes),
// the keys handled (8) and the undo history (a staff key's change; measured: a replay of 100,000
// staff keys peaks at 20 MB, 203 bytes a key in all). Two replays of 100,000 keys fit at once.
inline constexpr std::uint64_t replay_base_bytes = std::uint64_t{4} << 20;
inline constexpr std::uint64_t bytes_per_replayed_key = 320;
inline constexpr std::uint64_t replay_bytes(std::size_t keys) { return replay_base_bytes + keys * bytes_per_replayed_key; }
// And what the exercise's inputs add to each replay, for each byte of their text: the key frames
// read, equalised and held as the in-betweens' frames (14 frames of 24 bytes a point, for a point
// of about 25 bytes of text), the paths and their curves.
inline constexpr std::uint64_t bytes_per_input_byte = 32;

// A CSV field as RFC 4180 writes it: in double quotes, each quote doubled, when it holds a comma,
// a double quote, CR or LF; as it is otherwise. A field a spreadsheet would take for a formula
// (it begins with = + - @, a tab or CR and is not a number such as "+0.45"), and one that begins
// with an apostrophe already, begins with an apostrophe, so it is shown as the text it is: an answer's keys "= TEXT 0.45 ENTER" are not
// run, nor is a student's file named "=HYPERLINK(...).keys".
std::string csv_field(std::string_view text);

// A row as one CSV record ended by "\n" (LF: what Unix tools and spreadsheets read; a field that
// holds a line end is quoted, so records stay apart).
std::string grade_csv_line(const GradeRow& row);

// Where a recording departs from its exercise: the recording's line (0: none to name) and what
// differs, naming the exercise's line.
struct ScriptDeparture {
    int line = 0;
    std::string what;
};

// Whether `recording` is a recording of `exercise` (SPEC §3.2), compared as parsed scripts (comments,
// blank lines, layout, spacing, keyword case and the spelling of numbers do not count): the same
// INPUT lines in order; the same keys before the first GOAL line, START at the same key; the same
// GOAL lines and captions, in order, each on the same side of each GOAL line, and the captions up to
// the first GOAL line after the same keys. The student's keys stand anywhere after the first GOAL
// line. The first departure, or nullopt. `exercise_name` names the exercise's lines.
std::optional<ScriptDeparture> departure_from_exercise(const KeyScript& exercise, const KeyScript& recording,
                                                       const std::string& exercise_name);

// Whether a recording holds nothing at all (no key, no line but comments): nothing done.
bool is_blank_recording(const KeyScript& recording);

// `recording` with each goal's answer running to the next GOAL line (or the end): the keys after
// GOAL k and before GOAL k+1, captions included, answer goal k (SPEC §3.2), wherever --record put
// the student's keys.
KeyScript with_answers_to_next_goal(KeyScript recording);

// The keys after the first GOAL line (the student's, wherever they stand among the GOAL lines and
// captions), as script tokens separated by single spaces: what `--class` compares for same_as
// (comments and layout do not count). Empty when there are none, or no GOAL line.
std::string keys_after_goals(const KeyScript& recording);

// The answer's tokens as a row shows them: at most most_answer_characters characters, then
// "… (N keys)" with the answer's number of keys.
std::string answer_field(const KeyScript& script, const ScriptGoal& goal);

// The keys of goal `goal`'s answer in `script` (events [before_event, answer_end)), as script
// tokens separated by single spaces: a physical key by its script name (ENTER, LEFT, …), a
// printable character as itself, the keys of one TEXT line as "TEXT " and its text, a ';' typed
// alone as "TEXT ;". Empty when the goal has no answer (the exercise itself).
std::string answer_tokens(const KeyScript& script, const ScriptGoal& goal);

// The rows of a recording of the exercise that was replayed: one per goal of `recording`, in
// order, its verdict and value from `outcomes` (a goal with no outcome grades no, its value empty).
std::vector<GradeRow> replayed_rows(const GradeNames& names, const KeyScript& recording,
                                    const std::vector<GoalOutcome>& outcomes);

// The rows of a recording that did nothing (is_blank_recording): each goal of the exercise not
// reached, value and keys empty.
std::vector<GradeRow> blank_rows(const GradeNames& names, const KeyScript& exercise);

// The rows of a recording that was not replayed (GradeVerdict::other or ::error): one per goal of
// the exercise, value and keys empty.
std::vector<GradeRow> unreplayed_rows(const GradeNames& names, const KeyScript& exercise, GradeVerdict verdict);

} // namespace apcs
