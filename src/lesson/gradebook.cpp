#include "apcs/lesson/gradebook.h"

#include <map>

namespace apcs {

namespace {

// The cell of goal `goal` of `exercise`: "missing", or the row's verdict.
std::string cell(const StudentExercise& exercise, std::size_t goal)
{
    if (exercise.missing || goal >= exercise.rows.size())
        return "missing";
    return std::string(verdict_name(exercise.rows[goal].reached));
}

std::size_t goals_reached(const StudentWork& student)
{
    std::size_t reached = 0;
    for (const StudentExercise& exercise : student.exercises)
        for (const GradeRow& row : exercise.rows)
            reached += row.reached == GradeVerdict::yes ? 1 : 0;
    return reached;
}

std::size_t goal_count(const std::vector<GradebookExercise>& exercises)
{
    std::size_t count = 0;
    for (const GradebookExercise& exercise : exercises)
        count += exercise.goals.size();
    return count;
}

// The digests of the keys after the GOAL lines of every exercise, in order; nullopt when no
// exercise has any.
std::optional<std::vector<std::size_t>> all_answer_keys(const StudentWork& student)
{
    std::vector<std::size_t> digests;
    bool any = false;
    for (const StudentExercise& exercise : student.exercises) {
        digests.push_back(exercise.answer_digest);
        any = any || exercise.answer_digest != 0;
    }
    return any ? std::optional<std::vector<std::size_t>>(std::move(digests)) : std::nullopt;
}

// One goal's lines of the feedback: the verdict, then what was wanted on a line of its own, so that
// a sheet reads in 80 columns.
std::string goal_feedback_line(const StudentExercise& exercise, std::size_t goal, const std::string& wanted)
{
    std::string line = "  goal " + std::to_string(goal + 1) + ": ";
    const std::string wanted_line = "    wanted: " + wanted + "\n";
    if (exercise.missing || goal >= exercise.rows.size())
        return line + "not handed in\n" + wanted_line;
    const GradeRow& row = exercise.rows[goal];
    switch (row.reached) {
    case GradeVerdict::yes: line += "reached"; break;
    case GradeVerdict::no: line += "not reached"; break;
    case GradeVerdict::other: line += "not graded: the recording is not of this exercise"; break;
    case GradeVerdict::error: line += "not graded: the recording could not be replayed"; break;
    }
    if (!row.said.empty())
        line += ", " + row.said;
    else if (row.reached == GradeVerdict::no)
        line += ", nothing done";
    return line + "\n" + wanted_line;
}

// `text` as lines of at most 79 columns where it has spaces to break at: the first after `first`,
// the rest after `rest` (a word longer than a line stays whole: a file's path).
std::string wrapped(const std::string& text, const std::string& first, const std::string& rest)
{
    constexpr std::size_t columns = 79;
    std::string lines = first;
    std::size_t line_start = 0;
    std::size_t word = 0;
    while (word < text.size()) {
        const std::size_t end = std::min(text.find(' ', word), text.size());
        const bool line_empty = lines.size() - line_start == (line_start == 0 ? first.size() : rest.size());
        if (!line_empty && lines.size() - line_start + 1 + (end - word) > columns) {
            lines += '\n';
            line_start = lines.size();
            lines += rest;
        } else if (!line_empty) {
            lines += ' ';
        }
        lines += text.substr(word, end - word);
        word = end + 1;
    }
    return lines + '\n';
}

} // namespace

std::string gradebook_header(const std::vector<GradebookExercise>& exercises)
{
    std::string header = "student";
    for (const GradebookExercise& exercise : exercises)
        for (std::size_t goal = 0; goal < exercise.goals.size(); ++goal)
            header += ',' + csv_field(exercise.name + ':' + std::to_string(goal + 1));
    return header + ",reached,of,same_as";
}

std::vector<std::string> same_as(const std::vector<StudentWork>& students)
{
    std::map<std::vector<std::size_t>, std::vector<std::size_t>> by_keys;
    std::vector<std::optional<std::vector<std::size_t>>> keys;
    for (std::size_t index = 0; index < students.size(); ++index) {
        keys.push_back(all_answer_keys(students[index]));
        if (keys.back())
            by_keys[*keys.back()].push_back(index);
    }
    std::vector<std::string> alike(students.size());
    for (std::size_t index = 0; index < students.size(); ++index) {
        if (!keys[index])
            continue;
        for (const std::size_t other : by_keys[*keys[index]])
            if (other != index)
                alike[index] += (alike[index].empty() ? "" : "; ") + students[other].name;
    }
    return alike;
}

std::string gradebook_line(const StudentWork& student, const std::vector<GradebookExercise>& exercises,
                           const std::string& alike)
{
    std::string line = csv_field(student.name);
    for (std::size_t exercise = 0; exercise < exercises.size(); ++exercise)
        for (std::size_t goal = 0; goal < exercises[exercise].goals.size(); ++goal)
            line += ',' + cell(student.exercises[exercise], goal);
    line += ',' + std::to_string(goals_reached(student)) + ',' + std::to_string(goal_count(exercises));
    return line + ',' + csv_field(alike) + '\n';
}

std::string feedback_text(const StudentWork& student, const std::vector<GradebookExercise>& exercises)
{
    std::string text = "Feedback for " + student.name + ": " + std::to_string(goals_reached(student)) + " of " +
                       std::to_string(goal_count(exercises)) + " goals reached.\n";
    for (std::size_t index = 0; index < exercises.size(); ++index) {
        const StudentExercise& exercise = student.exercises[index];
        text += '\n' + exercises[index].name + (exercise.missing ? ": no recording handed in\n" : "\n");
        if (!exercise.why.empty())
            text += wrapped(exercise.why, "  ", "    ");
        for (std::size_t goal = 0; goal < exercises[index].goals.size(); ++goal)
            text += goal_feedback_line(exercise, goal, exercises[index].goals[goal]);
    }
    return text;
}

} // namespace apcs
