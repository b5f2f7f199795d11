#include "apcs/cli/grade_command.h"

#include "grade_run.h"

#include "apcs/base/utf8.h"
#include "memory_limit.h"
#include "report.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/unfinished_files.h"
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

// A student of the class: the folder, and whether it could be reached (a link to nothing could not).
struct StudentFolder {
    fs::path path;
    bool reached = true;
};

// The student folders of DIR, sorted by name: every folder in it, and every link in it to a folder
// or to nothing (each recording of a link to nothing is an error row: a student is never left out
// unsaid); hidden ones (".name") and files left out. The problem if DIR cannot be read.
Expected<std::vector<StudentFolder>> student_folders(const fs::path& class_folder)
{
    std::error_code error;
    std::vector<StudentFolder> students;
    for (fs::directory_iterator entry(class_folder, error), end; !error && entry != end; entry.increment(error)) {
        if (entry->path().filename().string().starts_with('.'))
            continue;
        std::error_code unreached;
        const bool folder = fs::is_directory(entry->path(), unreached);
        std::error_code not_a_link;
        if (folder || (unreached && entry->is_symlink(not_a_link)))
            students.push_back({entry->path(), !unreached});
    }
    if (error)
        return Diagnostic{class_folder.string(), 0, "cannot read the class folder: " + error.message()};
    std::ranges::sort(students, {}, &StudentFolder::path);
    return students;
}

// Whether the student handed in `recording`: a name that is not there is missing; one that cannot
// be looked at (a folder the teacher may not read) is handed in, so that reading it gives the reason.
bool handed_in(const fs::path& recording)
{
    std::error_code error;
    const fs::file_status status = fs::symlink_status(recording, error);
    return fs::exists(status) || (error && error != std::errc::no_such_file_or_directory);
}

// Two exercises of one file name would name the same recording in each student's folder.
std::optional<std::string> same_file_names(const std::vector<fs::path>& exercises)
{
    for (std::size_t first = 0; first < exercises.size(); ++first)
        for (std::size_t second = first + 1; second < exercises.size(); ++second)
            if (exercises[first].filename() == exercises[second].filename())
                return exercises[first].string() + " and " + exercises[second].string();
    return std::nullopt;
}

// Whether `inner` is `outer` or lies inside it, as the file system resolves both.
bool inside(const fs::path& inner, const fs::path& outer)
{
    std::error_code error;
    const fs::path resolved_outer = fs::weakly_canonical(outer, error);
    const fs::path resolved_inner = fs::weakly_canonical(inner, error);
    const auto [end, unused] = std::mismatch(resolved_outer.begin(), resolved_outer.end(), resolved_inner.begin(),
                                             resolved_inner.end());
    return !error && end == resolved_outer.end();
}

// `text` on `stream`, unless a stop has begun: a stop on another thread waits for it to be written
// whole (make_unless_stopping), so a grade stopped by a signal never leaves a row cut short.
void tell_whole(std::ostream& stream, const std::string& text)
{
    if (!text.empty())
        make_unless_stopping([&] { stream << text << std::flush; });
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

// Each student's feedback written as FEEDBACK/STUDENT.txt; false when one could not be (each
// problem on `err`; the others are written).
bool write_feedback(const fs::path& folder, const std::vector<StudentWork>& students,
                    const std::vector<StudentFolder>& student_folders, const std::vector<GradebookExercise>& exercises,
                    std::ostream& err)
{
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) {
        err << folder.string() << ": cannot make the feedback folder: " << error.message() << '\n';
        return false;
    }
    bool every_one = true;
    for (std::size_t index = 0; index < students.size(); ++index) {
        const fs::path target = folder / (student_folders[index].path.filename().string() + ".txt");
        if (const auto written = write_file_atomically(target, feedback_text(students[index], exercises)); !written) {
            err << escape_controls(written.error().to_string()) << '\n';
            every_one = false;
        }
    }
    return every_one;
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
        tell_whole(err, grade.messages);
        tell_whole(out, rows);
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
    if (const std::optional<std::string> both = same_file_names(request.exercises)) {
        err << "apcs grade --class: " << escape_controls(*both)
            << " have one file name; expected exercises of different names, since each student's recording is "
               "named as its exercise\n";
        return ExitStatus::bad_usage;
    }
    if (request.feedback && inside(*request.feedback, request.class_folder)) {
        err << "apcs grade --class: --feedback " << escape_controls(request.feedback->string())
            << " is inside the class folder; expected a folder outside it (a folder in the class folder is a "
               "student)\n";
        return ExitStatus::bad_usage;
    }
    const Expected<std::vector<StudentFolder>> students = student_folders(request.class_folder);
    if (!students)
        return report_bad_input(students.error(), err);
    GradeRun run(*limit, request.work_budget);
    if (const std::optional<ExitStatus> refused = prepare(run, request.exercises, options, err))
        return *refused;
    std::vector<GradeTask> tasks;
    std::vector<StudentWork> work;
    for (const StudentFolder& student : *students) {
        work.push_back({escape_controls(student.path.filename().string()), {}});
        if (!student.reached)
            err << escape_controls(student.path.string()) << ": a link to no folder; its recordings are errors\n";
        for (std::size_t exercise = 0; exercise < run.exercise_count(); ++exercise) {
            // Each recording named as its exercise; a name that is not there is missing (not an error).
            const fs::path recording = student.path / fs::path(run.exercise(exercise).name).filename();
            const bool given = !student.reached || handed_in(recording);
            tasks.push_back({exercise, given ? std::optional<fs::path>(recording) : std::nullopt});
        }
    }
    bool every_one_graded = true;
    run.grade(tasks, options, [&](std::size_t index, RecordingGrade grade) {
        StudentExercise handed{!tasks[index].recording, std::move(grade.rows), grade.answer_digest,
                               first_reason(grade.messages)};
        work[index / run.exercise_count()].exercises.push_back(std::move(handed));
        tell_whole(err, grade.messages);
        every_one_graded = every_one_graded && !grade.error;
    });
    const std::vector<GradebookExercise> exercises = gradebook_exercises(run);
    const std::vector<std::string> alike = same_as(work);
    std::string book = gradebook_header(exercises) + '\n';
    for (std::size_t student = 0; student < work.size(); ++student)
        book += gradebook_line(work[student], exercises, alike[student]);
    tell_whole(out, book);
    if (request.feedback && !write_feedback(*request.feedback, work, *students, exercises, err))
        return ExitStatus::bad_input;
    return every_one_graded ? ExitStatus::success : ExitStatus::bad_input;
}

} // namespace apcs
