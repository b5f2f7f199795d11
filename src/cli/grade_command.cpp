#include "apcs/cli/grade_command.h"

#include "apcs/base/utf8.h"
#include "apcs/cli/memory_limit.h"
#include "apcs/cli/report.h"
#include "apcs/cli/script_options.h"
#include "apcs/cli/session_command.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/input_check.h"
#include "apcs/formats/unfinished_files.h"
#include "apcs/lesson/grade.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace apcs {

namespace {

namespace fs = std::filesystem;

// A folder of this run's own, made as mkdtemp makes one (mode 0700: no other user reads a
// student's replay or swaps a file in it) and removed with everything in it when the run ends,
// whichever way: at the end, after an error, or by the handler of a signal that stops APCS
// (unfinished_files.h), which finds it by its parent folder's descriptor. Everything in it is
// reached through its own descriptor (/proc/self/fd/N), never its name: in a TMPDIR others may
// write, the name can be swapped for a link to another folder while grade runs, and what is made
// and removed must stay in the folder made.
class PrivateFolder {
public:
    PrivateFolder() = default;
    PrivateFolder(const PrivateFolder&) = delete;
    PrivateFolder& operator=(const PrivateFolder&) = delete;
    ~PrivateFolder()
    {
        if (m_self >= 0) {
            std::error_code ignored;
            for (const fs::directory_entry& entry : fs::directory_iterator(m_path, ignored))
                fs::remove_all(entry.path(), ignored);
            // By the name only once empty: a link put in its place is not a folder, and stays.
            ::unlinkat(m_parent, m_name.c_str(), AT_REMOVEDIR);
            ::close(m_self);
        }
        m_known.reset();
        if (m_parent >= 0)
            ::close(m_parent);
    }

    // The folder made under the system's temporary folder (TMPDIR, else /tmp); the problem if not.
    Expected<void> make()
    {
        std::error_code error;
        const fs::path temporary = fs::temp_directory_path(error);
        if (error) {
            // The folder the environment names (std::filesystem reads TMPDIR first), said by name.
            const char* named = std::getenv("TMPDIR");
            const std::string which = named != nullptr ? "TMPDIR=" + escape_controls(named) : "the temporary folder";
            return Diagnostic{"apcs", 0, "grade: " + which + " is not a folder to grade in (" + error.message() +
                                             "); set TMPDIR to a folder, or unset it for /tmp"};
        }
        m_parent = ::open(temporary.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
        std::string name = "apcs-grade-XXXXXX";
        if (m_parent < 0 || create_unfinished_folder(m_parent, name, m_known) != 0 ||
            (m_self = ::openat(m_parent, name.c_str(), O_PATH | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC)) < 0) {
            const int reason = errno; // before the message's allocations
            return Diagnostic{"apcs", 0, "grade: cannot make a folder in " + temporary.string() + ": " +
                                             std::strerror(reason)};
        }
        m_name = name;
        m_path = "/proc/self/fd/" + std::to_string(m_self);
        return ok;
    }
    // The folder as its descriptor names it.
    const fs::path& path() const { return m_path; }

private:
    int m_parent = -1;
    int m_self = -1;
    std::optional<UnfinishedFolder> m_known;
    std::string m_name;
    fs::path m_path;
};

// What every recording is graded against: the exercise as read, its name as typed, and the
// private copy of its inputs.
struct Exercise {
    KeyScript script;
    CommonOptions options;           // apcs's defaults and the exercise's OPTIONS line: its task
    std::string name;
    fs::path inputs;                 // the folder of the checked copies, in the private folder
    std::vector<fs::path> copies;    // each copy, named as beside the exercise
};

// EXERCISE.keys read and parsed as --keys reads a script, its OPTIONS taken over `options`; it
// must have goals to grade and inputs to replay on. The problem on `err` and the exit status, or
// nullopt.
std::optional<ExitStatus> read_exercise(const fs::path& file, Exercise& exercise, const CommonOptions& options,
                                        std::ostream& err)
{
    const Expected<std::string> text = read_text_file(file, max_key_script_bytes);
    if (!text)
        return report_bad_input(text.error(), err);
    Expected<KeyScript> parsed = parse_captioned_key_script(*text, file.string());
    if (!parsed)
        return report_bad_input(parsed.error(), err);
    if (parsed->goals.empty())
        return report_bad_input({file.string(), 0, "has no GOAL line; apcs grade grades an exercise's goals"}, err);
    if (parsed->inputs.empty())
        return report_bad_input({file.string(), 0,
                                 "names no input (INPUT NAME CRC32 XXXXXXXX lines); apcs grade replays each "
                                 "recording on fresh copies of the exercise's inputs"},
                                err);
    exercise.options = options;
    if (const Expected<void> taken = take_script_options(parsed->options, file.string(), exercise.options); !taken)
        return report_bad_input(taken.error(), err);
    exercise.script = std::move(*parsed);
    return std::nullopt;
}

// The file `from` copied as `to`, which the owner may write (the session rewrites an accepted
// path file, as it does in a student's copy, whatever the teacher's file's mode).
Expected<void> copy_writable(const fs::path& from, const fs::path& to)
{
    std::error_code error;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, error);
    if (!error)
        fs::permissions(to, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::add, error);
    if (error)
        return Diagnostic{"apcs", 0, "grade: cannot copy " + from.string() + " to " + to.string() + ": " +
                                         error.message()};
    return ok;
}

// The exercise's inputs beside it, checked, copied into the private folder and checked again
// there, so that what the recordings are replayed on is what the exercise names even if the
// teacher's files change meanwhile. The problem on `err` and the exit status, or nullopt.
std::optional<ExitStatus> copy_inputs(Exercise& exercise, const fs::path& exercise_file, std::ostream& err)
{
    const fs::path beside = exercise_file.has_parent_path() ? exercise_file.parent_path() : fs::path(".");
    if (const Expected<void> checked =
            check_script_inputs(exercise.script.inputs, beside, exercise.name, InputFolder::exercise);
        !checked)
        return report_bad_input(checked.error(), err);
    std::error_code error;
    if (fs::create_directory(exercise.inputs, error); error)
        return report_bad_input({"apcs", 0, "grade: cannot make " + exercise.inputs.string() + ": " + error.message()},
                                err);
    for (const ScriptInput& input : exercise.script.inputs) {
        // The file as the check found it: another case of its name is the same file (as DOS had it).
        const fs::path found = resolve_input_path(beside / input.name);
        exercise.copies.push_back(exercise.inputs / found.filename());
        if (const Expected<void> copied = copy_writable(found, exercise.copies.back()); !copied)
            return report_bad_input(copied.error(), err);
    }
    if (const Expected<void> checked = check_script_inputs(exercise.script.inputs, exercise.inputs, exercise.name);
        !checked)
        return report_bad_input(checked.error(), err);
    return std::nullopt;
}

// A work folder holding nothing but fresh copies of the checked inputs, as a student's copy of the
// exercise is before the session.
Expected<void> fresh_work_folder(const Exercise& exercise, const fs::path& work)
{
    std::error_code error;
    fs::remove_all(work, error);
    if (!error)
        fs::create_directory(work, error);
    if (error)
        return Diagnostic{"apcs", 0, "grade: cannot make " + work.string() + ": " + error.message()};
    for (const fs::path& copy : exercise.copies)
        if (const Expected<void> copied = copy_writable(copy, work / copy.filename()); !copied)
            return copied;
    return ok;
}

// The recording's script, or the reason it cannot be graded (FILE:LINE on `err`): unreadable,
// not a key script, or too long to replay (SPEC §3.2: beyond most_recording_keys keys). Only a
// regular file is read (read_text_file): a FIFO or a device is refused without being opened.
std::optional<KeyScript> read_recording(const fs::path& recording, std::ostream& err)
{
    const Expected<std::string> text = read_text_file(recording, most_recording_bytes);
    if (!text) {
        err << text.error().to_string() << '\n';
        return std::nullopt;
    }
    Expected<KeyScript> parsed = parse_captioned_key_script(*text, recording.string());
    if (!parsed) {
        err << parsed.error().to_string() << '\n';
        return std::nullopt;
    }
    if (parsed->events.size() > most_recording_keys) {
        err << Diagnostic{recording.string(), 0,
                          "too long: " + std::to_string(parsed->events.size()) + " keys, at most " +
                              std::to_string(most_recording_keys) + " are graded"}
                   .to_string()
            << '\n';
        return std::nullopt;
    }
    return std::move(*parsed);
}

// Why a recording is another exercise's, on `err`: its first line that departs, or the option
// that sets another task.
void say_other(const fs::path& recording, const Exercise& exercise, const ScriptDeparture& departure, std::ostream& err)
{
    err << Diagnostic{recording.string(), departure.line,
                      "not a recording of " + exercise.name + ": " + departure.what}
               .to_string()
        << '\n';
}

// One recording's rows: error when it cannot be read or replayed, other when it is another
// exercise's, else each goal as its replay in `work` left it. `work` is removed after the replay.
std::vector<GradeRow> grade_recording(const Exercise& exercise, const fs::path& recording,
                                      const CommonOptions& options, const fs::path& work, std::ostream& err)
{
    // The CSV is read on the teacher's terminal too (cat grades.csv): names as messages print them.
    const GradeNames names{escape_controls(recording.string()), escape_controls(exercise.name)};
    const std::optional<KeyScript> script = read_recording(recording, err);
    if (!script)
        return unreplayed_rows(names, exercise.script, GradeVerdict::error);
    if (is_blank_recording(*script))
        return blank_rows(names, exercise.script);
    if (const std::optional<ScriptDeparture> departure =
            departure_from_exercise(exercise.script, *script, exercise.name)) {
        say_other(recording, exercise, *departure, err);
        return unreplayed_rows(names, exercise.script, GradeVerdict::other);
    }
    // The student's staff step, in-between count ... as the recording's OPTIONS line has them; a
    // recording whose options set another task (another starting staff, in-between count ...) is
    // of another exercise, as one with other GOAL lines is.
    CommonOptions replay_options = options;
    if (const Expected<void> taken = take_script_options(script->options, recording.string(), replay_options); !taken) {
        err << taken.error().to_string() << '\n';
        return unreplayed_rows(names, exercise.script, GradeVerdict::error);
    }
    if (const std::optional<std::string> changed = changed_task_option(exercise.options, replay_options)) {
        say_other(recording, exercise, {script->options.line_number, "OPTIONS sets another task (" + *changed + ")"},
                  err);
        return unreplayed_rows(names, exercise.script, GradeVerdict::other);
    }
    if (const Expected<void> made = fresh_work_folder(exercise, work); !made) {
        err << made.error().to_string() << '\n';
        return unreplayed_rows(names, exercise.script, GradeVerdict::error);
    }
    // The report is the grade: a replay's "goal not reached" and the like are not shown.
    std::ostream unheard(nullptr);
    const KeyScript answered = with_answers_to_next_goal(*script);
    const HeadlessReplay replayed = replay_in_folder(answered, recording.string(), replay_options, work, unheard);
    std::error_code ignored;
    fs::remove_all(work, ignored);
    // A file the session could not write changed where the keys went: no verdict stands.
    if (replayed.unwritten) {
        err << recording.string() << ": not graded: " << replayed.unwritten->to_string() << '\n';
        return unreplayed_rows(names, exercise.script, GradeVerdict::error);
    }
    std::vector<GradeRow> rows = replayed_rows(names, answered, replayed.goals);
    if (script->options.words != exercise.script.options.words)
        for (GradeRow& row : rows)
            row.options = script->options.words;
    return rows;
}

} // namespace

ExitStatus run_grade_command(const GradeRequest& request, const CommonOptions& options, std::ostream& out,
                             std::ostream& err)
{
    if (const Expected<std::uint64_t> limit = memory_limit(options); !limit) {
        err << limit.error().to_string() << '\n';
        return ExitStatus::bad_usage;
    }
    Exercise exercise;
    exercise.name = request.exercise.string();
    if (const std::optional<ExitStatus> refused = read_exercise(request.exercise, exercise, options, err))
        return *refused;
    PrivateFolder folder;
    if (const Expected<void> made = folder.make(); !made)
        return report_bad_input(made.error(), err);
    exercise.inputs = folder.path() / "inputs";
    if (const std::optional<ExitStatus> refused = copy_inputs(exercise, request.exercise, err))
        return *refused;
    out << grade_csv_header << '\n' << std::flush;
    bool every_one_graded = true;
    for (const fs::path& recording : request.recordings) {
        // A recording's rows go out together as soon as they are graded: a grade stopped by a
        // signal has printed whole rows only, and every row it had graded.
        std::string rows;
        for (const GradeRow& row : grade_recording(exercise, recording, options, folder.path() / "work", err)) {
            rows += grade_csv_line(row);
            every_one_graded = every_one_graded && row.reached != GradeVerdict::error;
        }
        out << rows << std::flush;
    }
    return every_one_graded ? ExitStatus::success : ExitStatus::bad_input;
}

} // namespace apcs
