#include "apcs/lesson/gradebook.h"

#include <catch2/catch.hpp>

using namespace apcs;

namespace {

// A student's work on one exercise of one goal: its verdict and keys (as grade digests them).
StudentExercise handed(GradeVerdict verdict, const std::string& keys, std::string said = {})
{
    GradeRow row;
    row.reached = verdict;
    row.said = std::move(said);
    return {false, {row}, keys.empty() ? 0 : std::hash<std::string>{}(keys) | 1, {}};
}

const std::vector<GradebookExercise> two_exercises{{"ex-1", {"tension within +0.40 to +0.60"}},
                                                   {"ex-2", {"bias within +0.20 to +0.40", "the curve within 0.10"}}};

} // namespace

TEST_CASE("The gradebook's header has a column per goal of each exercise", "[lesson][gradebook]")
{
    REQUIRE(gradebook_header(two_exercises) == "student,ex-1:1,ex-2:1,ex-2:2,reached,of,same_as");
    REQUIRE(gradebook_header({{"a,b", {"x"}}}) == "student,\"a,b:1\",reached,of,same_as");
}

TEST_CASE("A student's row counts the goals reached of all, missing ones included, and quotes a name with a comma",
          "[lesson][gradebook]")
{
    StudentWork work{"Smith, Ann", {handed(GradeVerdict::yes, "L"), {}}};
    work.exercises[1].missing = true;
    REQUIRE(gradebook_line(work, two_exercises, "bob") == "\"Smith, Ann\",yes,missing,missing,1,3,bob\n");
    StudentExercise two_goals = handed(GradeVerdict::other, "6");
    two_goals.rows.push_back(two_goals.rows.front());
    REQUIRE(gradebook_line({"x", {handed(GradeVerdict::error, {}), two_goals}}, two_exercises, {}) ==
            "x,error,other,other,0,3,\n");
}

TEST_CASE("same_as names the students whose keys after the GOAL lines are the same in every exercise",
          "[lesson][gradebook]")
{
    const std::vector<StudentWork> students{
        {"ann", {handed(GradeVerdict::yes, "L L L 6"), handed(GradeVerdict::yes, "6 6")}},
        {"bob", {handed(GradeVerdict::yes, "L L L 6"), handed(GradeVerdict::yes, "6 6")}},
        {"cid", {handed(GradeVerdict::yes, "L L L 6"), handed(GradeVerdict::yes, "6 6 6")}},
        {"dee", {handed(GradeVerdict::yes, "L L L 6"), handed(GradeVerdict::yes, "6 6")}},
        // Two who did nothing are not alike.
        {"eve", {handed(GradeVerdict::no, ""), handed(GradeVerdict::no, "")}},
        {"fay", {handed(GradeVerdict::no, ""), handed(GradeVerdict::no, "")}},
        // The same keys under the other exercise are not the same work.
        {"gus", {handed(GradeVerdict::yes, "6 6"), handed(GradeVerdict::yes, "L L L 6")}},
        // Nor are the same keys split otherwise between the exercises.
        {"hal", {handed(GradeVerdict::yes, "L L L 6 6"), handed(GradeVerdict::yes, "6")}},
        // A name with a space, a comma or a quote stays whole.
        {"jo, \"j\" lee", {handed(GradeVerdict::yes, "6 6"), handed(GradeVerdict::yes, "L L L 6")}},
    };
    REQUIRE(same_as(students) ==
            std::vector<std::string>{"bob; dee", "ann; dee", "", "ann; bob", "", "", "jo, \"j\" lee", "", "gus"});
    REQUIRE(gradebook_line(students[6], two_exercises, same_as(students)[6]) ==
            "gus,yes,yes,missing,2,3,\"jo, \"\"j\"\" lee\"\n");
}

TEST_CASE("A reason too long for a line of the feedback wraps at 79 columns between words", "[lesson][gradebook]")
{
    StudentExercise other = handed(GradeVerdict::other, "6");
    other.why = "class/lee/exercise-2-continuity.keys:20: not a recording of exercise-2-continuity.keys: GOAL VALUE "
                "TENSION 0.4 0.6 where exercise-2-continuity.keys:17 has GOAL VALUE CONTINUITY -0.6 -0.4 after the "
                "same captions";
    const std::string text = feedback_text({"lee", {other}}, {{"ex-2", {"x"}}});
    REQUIRE(text == "Feedback for lee: 0 of 1 goals reached.\n"
                    "\nex-2\n"
                    "  class/lee/exercise-2-continuity.keys:20: not a recording of\n"
                    "    exercise-2-continuity.keys: GOAL VALUE TENSION 0.4 0.6 where\n"
                    "    exercise-2-continuity.keys:17 has GOAL VALUE CONTINUITY -0.6 -0.4 after the\n"
                    "    same captions\n"
                    "  goal 1: not graded: the recording is not of this exercise\n"
                    "    wanted: x\n");
}

TEST_CASE("A student's feedback names each goal reached or not, the value shown and what was wanted",
          "[lesson][gradebook]")
{
    StudentExercise second = handed(GradeVerdict::other, "6");
    second.rows.push_back(second.rows.front());
    second.why = "r.keys:3: not a recording of ex-2.keys: 'L' where ex-2.keys:3 has 'ENTER'";
    const StudentWork work{"ann", {handed(GradeVerdict::no, "6", "tension +0.05"), second}};
    REQUIRE(feedback_text(work, two_exercises) ==
            "Feedback for ann: 0 of 3 goals reached.\n"
            "\nex-1\n"
            "  goal 1: not reached, tension +0.05\n    wanted: tension within +0.40 to +0.60\n"
            "\nex-2\n"
            "  r.keys:3: not a recording of ex-2.keys: 'L' where ex-2.keys:3 has 'ENTER'\n"
            "  goal 1: not graded: the recording is not of this exercise\n    wanted: bias within +0.20 to +0.40\n"
            "  goal 2: not graded: the recording is not of this exercise\n    wanted: the curve within 0.10\n");
}
