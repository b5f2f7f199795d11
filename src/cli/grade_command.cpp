#include "apcs/cli/grade_command.h"

#include "grade_run.h"

#include "apcs/base/utf8.h"
#include "apcs/cli/memory_limit.h"
#include "apcs/cli/report.h"
#include "apcs/formats/file_io.h"
#include "apcs/lesson/gradebook.h"

#include <algorithm>
#include <ostream>
#include <string>
#include <system_error>
#include <vector>

namespace apcs {

namespace {

namespace fs = std::filesystem;

// The run's memory budget, or the refusal of an APCS_MEMORY_LIMIT that is no byte count.
std::optional<std::uint64_t> run_memory(const CommonOptions& options, std::ostream& err)
{
    const Expected<std::uint64_t> limit = memory_limit(options);
    if (!limit) {
        err << limit.error().to_string() << '\n';
        return std::nullopt;
    }
    return *limit;
}

// The run started and every exercise made ready, or the problem on `err` and the exit status.
std::optional<ExitStatus> prepare(GradeRun& run, const std::vector<fs::path>& exercises, const CommonOptions& options,
                                  std::ostream& err)
{
    if (const Expected<void> made = run.start(); !made)
        return report_bad_input(made.error(), err);
    for (const fs::path& exercise : exercises)
        if (const std::optional<ExitStatus> refused = run.add_exercise(exercise, options, err))
            return refused;
    return std::nullopt;
}

// The student folders of DIR, sorted by name: every folder in it (or link to one), hidden ones
// (".name") left out. The problem if DIR cannot be read.
Expected<std::vector<fs::path>> student_folders(const fs::path& class_folder)
{
    std::error_code error;
    std::vector<fs::path> students;
    for (fs::directory_iterator entry(class_folder, error), end; !error && entry != end; entry.increment(error)) {
        const std::string name = entry->path().filename().string();
        std::error_code kind;
        if (!name.starts_with('.') && entry->is_directory(kind))
            students.push_back(entry->path());
    }
    if (error)
        return Diagnostic{class_folder.string(), 0, "cannot read the class folder: " + error.message()};
    std::ranges::sort(students);
    return students;
}

// The gradebook's column names: each exercise's file name without ".keys", and its goals.
std::vector<GradebookExercise> gradebook_exercises(const GradeRun& run)
{
    std::vector<GradebookExercise> exercises;
    for (std::size_t index = 0; index < run.exercise_count(); ++index) {
        const GradeExercise& exercise = run.exercise(index);
        GradebookExercise column{escape_controls(fs::path(exercise.name).stem().string()), {}};
        for (const ScriptGoal& goal : exercise.script.goals)
            column.goals.push_back(goal_text(goal));
        exercises.push_back(std::move(column));
    }
    return exercises;
}

// The first line of a grade's messages (FILE:LINE: why), for the student's feedback.
std::string first_reason(const std::string& messages)
{
    return escape_controls(messages.substr(0, messages.find('\n')));
}

// Each student's feedback written as FEEDBACK/STUDENT.txt; false after the first that could not be
// (the problem on `err`).
bool write_feedback(const fs::path& folder, const std::vector<StudentWork>& students,
                    const std::vector<fs::path>& student_paths, const std::vector<GradebookExercise>& exercises,
                    std::ostream& err)
{
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) {
        err << folder.string() << ": cannot make the feedback folder: " << error.message() << '\n';
        return false;
    }
    for (std::size_t index = 0; index < students.size(); ++index) {
        const fs::path target = folder / (student_paths[index].filename().string() + ".txt");
        if (const auto written = write_file_atomically(target, feedback_text(students[index], exercises)); !written) {
            err << written.error().to_string() << '\n';
            return false;
        }
    }
    return true;
}

} // namespace

ExitStatus run_grade_command(const GradeRequest& request, const CommonOptions& options, std::ostream& out,
                             std::ostream& err)
{
    const std::optional<std::uint64_t> limit = run_memory(options, err);
    if (!limit)
        return ExitStatus::bad_usage;
    GradeRun run(*limit, request.work_budget);
    if (const std::optional<ExitStatus> refused = prepare(run, {request.exercise}, options, err))
        return *refused;
    std::vector<GradeTask> tasks;
    for (const fs::path& recording : request.recordings)
        tasks.push_back({0, recording});
    out << grade_csv_header << '\n' << std::flush;
    bool every_one_graded = true;
    run.grade(tasks, options, [&](std::size_t, RecordingGrade grade) {
        // A recording's rows go out together as soon as they and those before are graded: a grade
        // stopped by a signal has printed whole rows only, and every row it had told.
        std::string rows;
        for (const GradeRow& row : grade.rows)
            rows += grade_csv_line(row);
        err << grade.messages << std::flush;
        out << rows << std::flush;
        every_one_graded = every_one_graded && !grade.error;
    });
    return every_one_graded ? ExitStatus::success : ExitStatus::bad_input;
}

ExitStatus run_grade_class_command(const GradeClassRequest& request, const CommonOptions& options, std::ostream& out,
                                   std::ostream& err)
{
    const std::optional<std::uint64_t> limit = run_memory(options, err);
    if (!limit)
        return ExitStatus::bad_usage;
    const Expected<std::vector<fs::path>> students = student_folders(request.class_folder);
    if (!students)
        return report_bad_input(students.error(), err);
    GradeRun run(*limit, request.work_budget);
    if (const std::optional<ExitStatus> refused = prepare(run, request.exercises, options, err))
        return *refused;
    std::vector<GradeTask> tasks;
    std::vector<StudentWork> work;
    for (const fs::path& student : *students) {
        work.push_back({escape_controls(student.filename().string()), {}});
        for (std::size_t exercise = 0; exercise < run.exercise_count(); ++exercise) {
            // Each recording named as its exercise; a name that is not there is missing (not an error).
            const fs::path recording = student / fs::path(run.exercise(exercise).name).filename();
            std::error_code error;
            const bool handed_in = fs::exists(fs::symlink_status(recording, error));
            tasks.push_back({exercise, handed_in ? std::optional<fs::path>(recording) : std::nullopt});
        }
    }
    bool every_one_graded = true;
    run.grade(tasks, options, [&](std::size_t index, RecordingGrade grade) {
        StudentExercise handed{!tasks[index].recording, std::move(grade.rows), std::move(grade.answer_keys),
                               first_reason(grade.messages)};
        work[index / run.exercise_count()].exercises.push_back(std::move(handed));
        err << grade.messages << std::flush;
        every_one_graded = every_one_graded && !grade.error;
    });
    const std::vector<GradebookExercise> exercises = gradebook_exercises(run);
    const std::vector<std::string> alike = same_as(work);
    std::string book = gradebook_header(exercises) + '\n';
    for (std::size_t student = 0; student < work.size(); ++student)
        book += gradebook_line(work[student], exercises, alike[student]);
    out << book << std::flush;
    if (request.feedback && !write_feedback(*request.feedback, work, *students, exercises, err))
        return ExitStatus::bad_input;
    return every_one_graded ? ExitStatus::success : ExitStatus::bad_input;
}

} // namespace apcs
