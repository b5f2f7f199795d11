#pragma once

// The engine under `apcs grade` and `apcs grade --class` (grade_command.h): the exercises made
// ready in a private folder, and recordings graded on every core within the work and memory
// budgets of SPEC §3.2, their results handed back in the order asked.

#include "apcs/base/diagnostic.h"
#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/formats/key_script.h"
#include "apcs/lesson/grade.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace apcs {

// What every recording of one exercise is graded against: the exercise as read, its name as
// typed, and the private copy of its inputs.
struct GradeExercise {
    KeyScript script;
    CommonOptions options;        // apcs's defaults and the exercise's OPTIONS line: its task
    std::string name;             // as typed
    std::filesystem::path inputs; // the folder of the checked copies, in the private folder
    std::vector<std::filesystem::path> copies; // each copy, named as beside the exercise
    // What its inputs add to each replay's memory (bytes_per_input_byte of their text).
    std::uint64_t replay_bytes = 0;
};

// One recording to grade: of which exercise, and where (none: the student handed in nothing).
struct GradeTask {
    std::size_t exercise = 0;
    std::optional<std::filesystem::path> recording;
};

// One recording graded.
struct RecordingGrade {
    std::vector<GradeRow> rows; // one per goal of its exercise; none for a task without a recording
    std::string messages;       // for standard error, each line ended
    std::size_t answer_digest = 0; // a hash of keys_after_goals, for same_as; 0: no keys
    bool error = false;         // a row is an error
};

class PrivateFolder;
class ReplayMemoryGate;

class GradeRun {
public:
    // The run's memory (SPEC §3.2): the smaller of most_grade_bytes and `limit` (APCS_MEMORY_LIMIT);
    // the operations each replay may cost.
    GradeRun(std::uint64_t limit, std::uint64_t work_budget);
    ~GradeRun();
    GradeRun(const GradeRun&) = delete;
    GradeRun& operator=(const GradeRun&) = delete;

    // The private folder made (mkdtemp under TMPDIR, mode 0700; removed with everything in it when
    // the run ends, whichever way); the problem if not.
    Expected<void> start();
    // EXERCISE.keys read, checked (goals, inputs, OPTIONS) and its inputs copied, the run's next
    // exercise; else the problem written to `err` and the exit status.
    std::optional<ExitStatus> add_exercise(const std::filesystem::path& file, const CommonOptions& options,
                                           std::ostream& err);
    const GradeExercise& exercise(std::size_t index) const { return m_exercises[index]; }
    std::size_t exercise_count() const { return m_exercises.size(); }

    // Every task graded, on as many threads as the machine has cores, no more replays at once
    // than the memory holds; `done(index, grade)` is called for each in the tasks' order, on one
    // thread at a time, as soon as it and all before it are graded.
    void grade(const std::vector<GradeTask>& tasks, const CommonOptions& options,
               const std::function<void(std::size_t, RecordingGrade)>& done);

private:
    RecordingGrade grade_task(const GradeTask& task, std::size_t index, const CommonOptions& options);
    std::optional<std::vector<GoalOutcome>> replay_recording(const GradeExercise& exercise, const KeyScript& answered,
                                                             const std::filesystem::path& recording,
                                                             CommonOptions taken, std::size_t index, std::ostream& err);

    std::uint64_t m_replay_bytes;
    std::uint64_t m_work_budget;
    std::unique_ptr<PrivateFolder> m_folder;
    std::vector<GradeExercise> m_exercises;
    std::unique_ptr<ReplayMemoryGate> m_gate;
};

} // namespace apcs
