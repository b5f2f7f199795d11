#include "apcs/lesson/grade.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;

namespace {

KeyScript parsed(const std::string& text)
{
    Expected<KeyScript> script = parse_captioned_key_script(text, "test.keys");
    REQUIRE(script);
    return std::move(*script);
}

const std::string exercise_text = "INPUT way1.dat CRC32 1db7d833\nENTER ENTER\nSTART\n;; the task\n"
                                  "GOAL VALUE TENSION 0.40 0.60\n;; the end\n";

} // namespace

TEST_CASE("a CSV field is quoted only when it holds a comma or a quote or a line end", "[lesson][grade]")
{
    const auto [text, field] = GENERATE(table<std::string, std::string>({
        {"mine.keys", "mine.keys"},
        {"", ""},
        {"Doe, Jo.keys", "\"Doe, Jo.keys\""},
        {"say \"hi\".keys", "\"say \"\"hi\"\".keys\""},
        {"two\nlines", "\"two\nlines\""},
        {"carriage\rreturn", "\"carriage\rreturn\""},
        {"+0.45", "+0.45"},
        {"TEXT 0.45", "TEXT 0.45"},
    }));
    REQUIRE(csv_field(text) == field);
}

TEST_CASE("a CSV field a spreadsheet would run as a formula begins with an apostrophe, a number does not",
          "[lesson][grade]")
{
    const auto [text, field] = GENERATE(table<std::string, std::string>({
        {"= TEXT 0.45 ENTER", "'= TEXT 0.45 ENTER"},
        {"=HYPERLINK(\"http://x\")", "\"'=HYPERLINK(\"\"http://x\"\")\""},
        {"=1+1,2.keys", "\"'=1+1,2.keys\""},
        {"@SUM(A1).keys", "'@SUM(A1).keys"},
        {"-cmd.keys", "'-cmd.keys"},
        {"+", "'+"},
        {"+1.2.3", "'+1.2.3"},
        {"\tx.keys", "'\tx.keys"},
        {"\rx.keys", "\"'\rx.keys\""},
        {"+0.45", "+0.45"},
        {"-0.50", "-0.50"},
        {"-.5", "-.5"},
        {"1e+09", "1e+09"},
        {"-2.5E-3", "-2.5E-3"},
        {"L L = TEXT 0.45", "L L = TEXT 0.45"},
        // Already an apostrophe first: one more, so that dropping the first gives every field back.
        {"'=1+1.keys", "''=1+1.keys"},
        {"'jo.keys", "''jo.keys"},
    }));
    REQUIRE(csv_field(text) == field);
}

TEST_CASE("a grade row is one CSV record in the header's order", "[lesson][grade]")
{
    const GradeRow row{"a,b.keys", "ex.keys", "GOAL VALUE TENSION 0.4 0.6", GradeVerdict::yes, "+0.45", "L L L 6"};
    REQUIRE(grade_csv_header == "file,exercise,goal,reached,value,keys");
    REQUIRE(grade_csv_line(row) == "\"a,b.keys\",ex.keys,GOAL VALUE TENSION 0.4 0.6,yes,+0.45,L L L 6\n");
    REQUIRE(verdict_name(GradeVerdict::no) == "no");
    REQUIRE(verdict_name(GradeVerdict::other) == "other");
    REQUIRE(verdict_name(GradeVerdict::error) == "error");
}

TEST_CASE("an answer's keys are script tokens and a TEXT line's keys stay one token", "[lesson][grade]")
{
    const KeyScript script = parsed("ENTER\nGOAL VALUE TENSION 0.4 0.6\nL L\n=\nTEXT 0.45\nENTER LEFT\nTEXT ;\n"
                                    "SPACE\n;; the next caption ends the answer\n6\n");
    REQUIRE(script.goals.size() == 1);
    REQUIRE(answer_tokens(script, script.goals[0]) == "L L = TEXT 0.45 ENTER LEFT TEXT ; SPACE");
    const KeyScript unanswered = parsed(exercise_text);
    REQUIRE(answer_tokens(unanswered, unanswered.goals[0]).empty());
}

TEST_CASE("a recording is of the exercise when its GOAL and INPUT lines are the exercise's wherever they stand",
          "[lesson][grade]")
{
    const KeyScript exercise = parsed(exercise_text);
    REQUIRE(same_exercise(exercise, exercise));
    // --record writes one token a line, and the student's keys move the GOAL line down.
    REQUIRE(same_exercise(exercise, parsed("INPUT way1.dat CRC32 1DB7D833\nENTER\nENTER\nSTART\n8\n"
                                           "GOAL VALUE tension 0.4 0.6\nL\nL\n")));
    REQUIRE_FALSE(same_exercise(exercise, parsed("INPUT way1.dat CRC32 1db7d833\nGOAL VALUE TENSION 0.4 0.7\n")));
    REQUIRE_FALSE(same_exercise(exercise, parsed("INPUT way1.dat CRC32 1db7d833\nGOAL VALUE BIAS 0.4 0.6\n")));
    REQUIRE_FALSE(same_exercise(exercise, parsed("INPUT way2.dat CRC32 1db7d833\nGOAL VALUE TENSION 0.4 0.6\n")));
    REQUIRE_FALSE(same_exercise(exercise, parsed("GOAL VALUE TENSION 0.4 0.6\n")));
    REQUIRE_FALSE(same_exercise(exercise, parsed("INPUT way1.dat CRC32 1db7d833\nGOAL VALUE TENSION 0.4 0.6\n"
                                                 "GOAL VALUE TENSION 0.4 0.6\n")));
    REQUIRE_FALSE(same_exercise(exercise, parsed("ENTER\n")));
}

TEST_CASE("a replayed recording's rows take each goal's verdict and value from its outcome", "[lesson][grade]")
{
    const KeyScript recording = parsed("GOAL VALUE TENSION 0.4 0.6\nL L\nGOAL NEAR 0 1 2 0.1\n4\n"
                                       "GOAL VALUE BIAS -1 1\n");
    GoalProgress reached;
    reached.reached = true;
    reached.value = "+0.45";
    GoalProgress far;
    far.value = "0.35";
    const std::vector<GoalOutcome> outcomes{{0, GoalOutcome::Verdict::reached, reached, 2},
                                            {1, GoalOutcome::Verdict::not_reached, far, 3}};
    const GradeNames names{"mine.keys", "ex.keys"};
    const std::vector<GradeRow> rows = replayed_rows(names, recording, outcomes);
    REQUIRE(rows == std::vector<GradeRow>{
                        {"mine.keys", "ex.keys", "GOAL VALUE TENSION 0.4 0.6", GradeVerdict::yes, "+0.45", "L L"},
                        {"mine.keys", "ex.keys", "GOAL NEAR 0 1 2 0.1", GradeVerdict::no, "0.35", "4"},
                        {"mine.keys", "ex.keys", "GOAL VALUE BIAS -1 1", GradeVerdict::no, "", ""},
                    });
    REQUIRE(unreplayed_rows(names, recording, GradeVerdict::other) ==
            std::vector<GradeRow>{
                {"mine.keys", "ex.keys", "GOAL VALUE TENSION 0.4 0.6", GradeVerdict::other, "", ""},
                {"mine.keys", "ex.keys", "GOAL NEAR 0 1 2 0.1", GradeVerdict::other, "", ""},
                {"mine.keys", "ex.keys", "GOAL VALUE BIAS -1 1", GradeVerdict::other, "", ""},
            });
}
