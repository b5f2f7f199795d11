#include "grade_run.h"

#include "apcs/animation/memory_budget.h"
#include "apcs/base/parallel_work.h"
#include "apcs/base/utf8.h"
#include "report.h"
#include "apcs/cli/script_options.h"
#include "apcs/cli/session_command.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/input_check.h"
#include "apcs/formats/unfinished_files.h"

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <ostream>
#include <sstream>
#include <system_error>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace apcs {

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
            // Never a throw in a destructor: each step's error is taken, not thrown.
            std::error_code ignored;
            for (fs::directory_iterator entry(m_path, ignored), end; !ignored && entry != end; entry.increment(ignored)) {
                std::error_code each;
                fs::remove_all(entry->path(), each);
            }
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
    // A new folder `name` in it, and `fill` run to put what it holds there, unless a stop has
    // begun (make_unless_stopping): a stop's removal never leaves one behind. The problem if not.
    Expected<void> make_folder(const std::string& name, const std::function<Expected<void>()>& fill) const
    {
        Expected<void> filled = ok;
        int reason = 0;
        const bool made = make_unless_stopping([&] {
            if (::mkdirat(m_self, name.c_str(), 0700) != 0)
                reason = errno;
            else
                filled = fill();
        });
        if (!made || reason != 0)
            return Diagnostic{"apcs", 0, "grade: cannot make " + (m_path / name).string() + ": " +
                                             std::strerror(made ? reason : EINTR)};
        return filled;
    }

private:
    int m_parent = -1;
    int m_self = -1;
    std::optional<UnfinishedFolder> m_known;
    std::string m_name;
    fs::path m_path;
};

// Replays admitted while the bytes they are counted at fit the budget; one alone always is
// (the caller refuses one that never fits), so the run never waits forever.
class ReplayMemoryGate {
public:
    explicit ReplayMemoryGate(std::uint64_t budget) : m_budget(budget) {}
    void enter(std::uint64_t bytes)
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [&] { return m_running == 0 || m_used + bytes <= m_budget; });
        m_used += bytes;
        ++m_running;
    }
    void leave(std::uint64_t bytes)
    {
        {
            const std::lock_guard lock(m_mutex);
            m_used -= bytes;
            --m_running;
        }
        m_changed.notify_all();
    }

private:
    std::mutex m_mutex;
    std::condition_variable m_changed;
    std::uint64_t m_budget;
    std::uint64_t m_used = 0;
    std::size_t m_running = 0;
};

namespace {

// The gate held for one replay.
class GateEntry {
public:
    GateEntry(ReplayMemoryGate& gate, std::uint64_t bytes) : m_gate(gate), m_bytes(bytes) { gate.enter(bytes); }
    ~GateEntry() { m_gate.leave(m_bytes); }
    GateEntry(const GateEntry&) = delete;
    GateEntry& operator=(const GateEntry&) = delete;

private:
    ReplayMemoryGate& m_gate;
    std::uint64_t m_bytes;
};

// EXERCISE.keys read and parsed as --keys reads a script, its OPTIONS taken over `options`; it
// must have goals to grade and inputs to replay on. The problem on `err` and the exit status, or
// nullopt.
std::optional<ExitStatus> read_exercise(const fs::path& file, GradeExercise& exercise, const CommonOptions& options,
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
std::optional<ExitStatus> copy_inputs(GradeExercise& exercise, const fs::path& exercise_file, std::ostream& err)
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

// A new work folder `name` in `folder` holding nothing but fresh copies of the checked inputs, as a
// student's copy of the exercise is before the session.
Expected<void> fresh_work_folder(const GradeExercise& exercise, const PrivateFolder& folder, const std::string& name)
{
    return folder.make_folder(name, [&]() -> Expected<void> {
        for (const fs::path& copy : exercise.copies)
            if (const Expected<void> copied = copy_writable(copy, folder.path() / name / copy.filename()); !copied)
                return copied;
        return ok;
    });
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
    // Read no further than the most keys graded: a longer recording never takes their memory.
    Expected<KeyScript> parsed = parse_captioned_key_script(*text, recording.string(), most_recording_keys);
    if (!parsed) {
        err << parsed.error().to_string() << '\n';
        return std::nullopt;
    }
    return std::move(*parsed);
}

// Why a recording is another exercise's, on `err`: its first line that departs, or the option
// that sets another task.
void say_other(const fs::path& recording, const GradeExercise& exercise, const ScriptDeparture& departure,
               std::ostream& err)
{
    err << Diagnostic{recording.string(), departure.line, "not a recording of " + exercise.name + ": " + departure.what}
               .to_string()
        << '\n';
}

// The recording's task: the exercise's options with its own OPTIONS line over them, or nullopt
// when they set another task (the reason on `err`) or do not parse.
std::optional<CommonOptions> replay_options(const GradeExercise& exercise, const KeyScript& script,
                                            const fs::path& recording, const CommonOptions& options,
                                            GradeVerdict& refused, std::ostream& err)
{
    CommonOptions taken_options = options;
    if (const Expected<void> taken = take_script_options(script.options, recording.string(), taken_options); !taken) {
        err << taken.error().to_string() << '\n';
        refused = GradeVerdict::error;
        return std::nullopt;
    }
    if (const std::optional<std::string> changed = changed_task_option(exercise.options, taken_options)) {
        say_other(recording, exercise, {script.options.line_number, "OPTIONS sets another task (" + *changed + ")"},
                  err);
        refused = GradeVerdict::other;
        return std::nullopt;
    }
    return taken_options;
}

} // namespace

namespace {

// What the replays may take of a run's memory `limit`: the run's whole, less grade_own_bytes.
std::uint64_t bytes_for_replays(std::uint64_t limit)
{
    const std::uint64_t whole = std::min(limit, most_grade_bytes);
    return whole > grade_own_bytes ? whole - grade_own_bytes : 0;
}

} // namespace

GradeRun::GradeRun(std::uint64_t limit, std::uint64_t work_budget)
    : m_replay_bytes(bytes_for_replays(limit))
    , m_work_budget(work_budget)
    , m_folder(std::make_unique<PrivateFolder>())
    , m_gate(std::make_unique<ReplayMemoryGate>(m_replay_bytes))
{
}

GradeRun::~GradeRun() = default;

Expected<void> GradeRun::start() { return m_folder->make(); }

std::optional<ExitStatus> GradeRun::add_exercise(const fs::path& file, const CommonOptions& options, std::ostream& err)
{
    GradeExercise exercise;
    exercise.name = file.string();
    if (const std::optional<ExitStatus> refused = read_exercise(file, exercise, options, err))
        return refused;
    exercise.inputs = m_folder->path() / ("inputs-" + std::to_string(m_exercises.size()));
    if (const std::optional<ExitStatus> refused = copy_inputs(exercise, file, err))
        return refused;
    for (const fs::path& copy : exercise.copies) {
        std::error_code unsized;
        exercise.replay_bytes += bytes_per_input_byte * fs::file_size(copy, unsized);
    }
    m_exercises.push_back(std::move(exercise));
    return std::nullopt;
}

// `answered` replayed in a work folder of its own (removed after it) with the options `taken`: each
// goal's outcome, or none when no verdict stands (why, on `err`).
std::optional<std::vector<GoalOutcome>> GradeRun::replay_recording(const GradeExercise& exercise,
                                                                   const KeyScript& answered, const fs::path& recording,
                                                                   CommonOptions taken, std::size_t index,
                                                                   std::ostream& err)
{
    const std::string work_name = "work-" + std::to_string(index);
    const fs::path work = m_folder->path() / work_name;
    if (const Expected<void> made = fresh_work_folder(exercise, *m_folder, work_name); !made) {
        err << made.error().to_string() << '\n';
        return std::nullopt;
    }
    // The session's own checks (a path or the frames too large) against the replays' whole
    // budget: the same for every recording of the exercise, however many keys it has.
    taken.memory_limit = m_replay_bytes;
    // The report is the grade: a replay's "goal not reached" and the like are not shown.
    std::ostream unheard(nullptr);
    HeadlessReplay replayed = replay_in_folder(answered, recording.string(), taken, work, unheard, m_work_budget);
    std::error_code ignored;
    fs::remove_all(work, ignored);
    if (replayed.over_budget) {
        err << recording.string() << ": too long: its keys cost more than " << m_work_budget
            << " operations, the work budget of a replay\n";
        return std::nullopt;
    }
    // A file the session could not write changed where the keys went: no verdict stands.
    if (replayed.unwritten) {
        err << recording.string() << ": not graded: " << replayed.unwritten->to_string() << '\n';
        return std::nullopt;
    }
    return std::move(replayed.goals);
}

// One recording's rows: error when it cannot be read or replayed, other when it is another
// exercise's, else each goal as its replay in a work folder of its own left it.
RecordingGrade GradeRun::grade_task(const GradeTask& task, std::size_t index, const CommonOptions& options)
{
    RecordingGrade grade;
    if (!task.recording)
        return grade;
    const GradeExercise& exercise = m_exercises[task.exercise];
    const fs::path& recording = *task.recording;
    std::ostringstream err;
    // The CSV is read on the teacher's terminal too (cat grades.csv): names as messages print them.
    const GradeNames names{escape_controls(recording.string()), escape_controls(exercise.name)};
    const auto unreplayed = [&](GradeVerdict verdict) {
        grade.rows = unreplayed_rows(names, exercise.script, verdict);
        grade.messages = err.str();
        grade.error = verdict == GradeVerdict::error;
        return std::move(grade);
    };
    // The gate is entered before the recording is read: its text and keys take memory too. What
    // it is counted at comes from its size (a key takes a byte at least), then from its keys.
    std::error_code unsized;
    const std::uintmax_t size = std::min<std::uintmax_t>(fs::file_size(recording, unsized), most_recording_bytes);
    const std::uint64_t at_most = unsized ? replay_bytes(0) : size + replay_bytes(std::min<std::uintmax_t>(size, most_recording_keys));
    const GateEntry entry(*m_gate, std::min(at_most + exercise.replay_bytes, m_replay_bytes));
    const std::optional<KeyScript> script = read_recording(recording, err);
    if (!script)
        return unreplayed(GradeVerdict::error);
    if (const std::string keys = keys_after_goals(*script); !keys.empty())
        grade.answer_digest = std::hash<std::string>{}(keys) | 1; // never 0, which is "no keys"
    if (is_blank_recording(*script)) {
        grade.rows = blank_rows(names, exercise.script);
        return grade;
    }
    if (const std::optional<ScriptDeparture> departure = departure_from_exercise(exercise.script, *script, exercise.name)) {
        say_other(recording, exercise, *departure, err);
        return unreplayed(GradeVerdict::other);
    }
    GradeVerdict refused = GradeVerdict::error;
    std::optional<CommonOptions> taken = replay_options(exercise, *script, recording, options, refused, err);
    if (!taken)
        return unreplayed(refused);
    const std::uint64_t bytes = replay_bytes(script->events.size()) + exercise.replay_bytes;
    if (bytes > m_replay_bytes) {
        err << recording.string() << ": too long: its " << script->events.size() << " keys need about "
            << memory::byte_count_text(bytes) << " to replay, and apcs grade has "
            << memory::byte_count_text(m_replay_bytes)
            << " for replays (100 MB, or APCS_MEMORY_LIMIT when lower, less " << memory::byte_count_text(grade_own_bytes)
            << " for itself)\n";
        return unreplayed(GradeVerdict::error);
    }
    const KeyScript answered = with_answers_to_next_goal(*script);
    const std::optional<std::vector<GoalOutcome>> goals = replay_recording(exercise, answered, recording, *taken, index, err);
    if (!goals)
        return unreplayed(GradeVerdict::error);
    grade.rows = replayed_rows(names, answered, *goals);
    if (script->options.words != exercise.script.options.words)
        for (GradeRow& row : grade.rows)
            row.options = script->options.words;
    grade.messages = err.str();
    return grade;
}

void GradeRun::grade(const std::vector<GradeTask>& tasks, const CommonOptions& options,
                     const std::function<void(std::size_t, RecordingGrade)>& done)
{
    std::mutex finished_mutex;
    std::vector<std::optional<RecordingGrade>> finished(tasks.size());
    std::size_t next_told = 0;
    const std::size_t workers = std::max(1u, std::thread::hardware_concurrency());
    for_each_index_in_parallel(tasks.size(), workers, [&](std::size_t index) {
        RecordingGrade grade = grade_task(tasks[index], index, options);
        const std::lock_guard lock(finished_mutex);
        finished[index] = std::move(grade);
        for (; next_told < finished.size() && finished[next_told]; ++next_told) {
            done(next_told, std::move(*finished[next_told]));
            finished[next_told].reset();
        }
    });
}

} // namespace apcs
