#pragma once

#include "apcs/lesson/grade.h"

#include <optional>
#include <string>
#include <vector>

namespace apcs {

// The pure part of `apcs grade --class DIR EXERCISE.keys…` (SPEC §3.2): a class's gradebook, one
// row per student folder, and each student's feedback. src/cli/grade_command.cpp finds the
// folders and grades the recordings.

// One exercise of the gradebook: its column name (the exercise's file name without ".keys") and
// its goals, in order.
struct GradebookExercise {
    std::string name;
    std::vector<std::string> goals; // goal_text of each: what was wanted
};

// What one student handed in for one exercise.
struct StudentExercise {
    bool missing = true;          // no recording named as the exercise in the student's folder
    std::vector<GradeRow> rows;   // one per goal of the exercise when not missing
    std::size_t answer_digest = 0; // a hash of keys_after_goals of the recording; 0: no keys
    std::string why;              // for other and error: the first reason grade gave
};

struct StudentWork {
    std::string name; // the folder's name, as a message prints it (escape_controls)
    std::vector<StudentExercise> exercises; // parallel to the gradebook's exercises
};

// "student,exercise-1-tension:1,exercise-2-continuity:1,…,reached,of,same_as".
std::string gradebook_header(const std::vector<GradebookExercise>& exercises);

// For each student, the other students whose keys after the GOAL lines are the same in every
// exercise (and not all empty: students who did nothing are not alike), their names separated by
// "; " in the order given; "" for none.
std::vector<std::string> same_as(const std::vector<StudentWork>& students);

// A student's row: the name, a cell per goal of each exercise (yes, no, other, error or missing),
// the goals reached, the goals in all, and `alike` (same_as's), as one CSV record ended by "\n".
std::string gradebook_line(const StudentWork& student, const std::vector<GradebookExercise>& exercises,
                           const std::string& alike);

// The text of STUDENT.txt (--feedback): for each exercise and goal, reached or not, the value the
// student's path showed, and what was wanted; why a recording was not graded; the total.
std::string feedback_text(const StudentWork& student, const std::vector<GradebookExercise>& exercises);

} // namespace apcs
