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
    const GradeRow row{"a,b.keys", "ex.keys", "GOAL VALUE TENSION 0.4 0.6", GradeVerdict::yes, "+0.45", "L L L 6",
                       "--step 0.2", "tension within +0.40 to +0.60", "tension +0.45"};
    REQUIRE(grade_csv_header == "file,exercise,goal,reached,value,keys,options");
    REQUIRE(grade_csv_line(row) ==
            "\"a,b.keys\",ex.keys,GOAL VALUE TENSION 0.4 0.6,yes,+0.45,L L L 6,'--step 0.2\n");
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

TEST_CASE("a recording is of the exercise when it holds the exercise's lines up to the first GOAL and its GOAL "
          "lines and captions after, however written",
          "[lesson][grade]")
{
    const KeyScript exercise = parsed(exercise_text);
    const auto departure = [&exercise](const std::string& text) {
        return departure_from_exercise(exercise, parsed(text), "ex.keys");
    };
    REQUIRE_FALSE(departure(exercise_text));
    // --record writes one token a line, numbers and keywords as it spells them, comments dropped
    // and the student's keys after the GOAL line, before or after the closing caption.
    REQUIRE_FALSE(departure("input way1.dat CRC32 1DB7D833\nenter\nEnter\nstart\n;; the task\n"
                            "goal value tension 0.4 0.600 ; a comment\nL\n\n;; the end\nL\n"));
    REQUIRE_FALSE(departure("\xEF\xBB\xBFINPUT\tway1.dat CRC32 1db7d833\nENTER\tENTER\nSTART\n;; the task\n"
                            "GOAL VALUE TENSION 0.4 0.6\n;; the end\n"));
    // The answer moved above the GOAL line, or into the preamble with decoys after the GOAL.
    const auto moved = departure("INPUT way1.dat CRC32 1db7d833\nENTER ENTER\nSTART\nL L L\n;; the task\n"
                                 "GOAL VALUE TENSION 0.40 0.60\n;; the end\n");
    REQUIRE(moved);
    CHECK(moved->line == 4);
    CHECK(moved->what == "'L' where ex.keys:5 has the GOAL line (before the first GOAL line the keys are the "
                         "exercise's)");
    const auto preamble = departure("INPUT way1.dat CRC32 1db7d833\nENTER L ENTER\nSTART\n;; the task\n"
                                    "GOAL VALUE TENSION 0.40 0.60\n;; the end\n6\n");
    REQUIRE(preamble);
    CHECK(preamble->line == 2);
    CHECK(preamble->what.starts_with("'L' where ex.keys:2 has 'ENTER'"));
    const auto start = departure("INPUT way1.dat CRC32 1db7d833\nENTER\nSTART\nENTER\n;; the task\n"
                                 "GOAL VALUE TENSION 0.40 0.60\n;; the end\n");
    REQUIRE(start);
    CHECK(start->what == "START after 1 keys, where the exercise has it after 2");
    // Edited captions, another exercise's GOAL and INPUT lines, a caption moved across the GOAL.
    const auto caption = departure("INPUT way1.dat CRC32 1db7d833\nENTER ENTER\nSTART\n;; the task, easier\n"
                                   "GOAL VALUE TENSION 0.40 0.60\n;; the end\n");
    REQUIRE(caption);
    CHECK(caption->line == 4);
    CHECK(caption->what == "a caption that differs from ex.keys:4's");
    CHECK(departure("INPUT way1.dat CRC32 1db7d833\nENTER ENTER\nSTART\n;; the task\n"
                    "GOAL VALUE TENSION 0.4 0.7\n;; the end\n")
              ->what == "GOAL VALUE TENSION 0.4 0.7 where ex.keys:5 has GOAL VALUE TENSION 0.4 0.6 after the same "
                        "captions");
    CHECK(departure("INPUT way1.dat CRC32 1db7d833\nENTER ENTER\nSTART\n;; the task\n;; the end\n"
                    "GOAL VALUE TENSION 0.4 0.6\n")
              ->line == 6);
    CHECK(departure("INPUT way2.dat CRC32 1db7d833\nENTER ENTER\nSTART\n;; the task\nGOAL VALUE TENSION 0.4 0.6\n"
                    ";; the end\n")
              ->what == "INPUT way2.dat where ex.keys:1 has INPUT way1.dat with its checksum");
    CHECK(departure("ENTER\n")->what == "no INPUT way1.dat line, as ex.keys:1 has");
}

TEST_CASE("a recording of nothing but comments is blank: nothing done, not another exercise", "[lesson][grade]")
{
    REQUIRE(is_blank_recording(parsed("")));
    REQUIRE(is_blank_recording(parsed("; nothing\n\n")));
    REQUIRE_FALSE(is_blank_recording(parsed("ENTER\n")));
    REQUIRE_FALSE(is_blank_recording(parsed(";; a caption\n")));
}

TEST_CASE("in a recording the keys after GOAL k and before GOAL k+1 answer goal k, captions included, and a long "
          "answer's field is cut at 200 characters with its count of keys",
          "[lesson][grade]")
{
    const KeyScript recording = with_answers_to_next_goal(
        parsed("ENTER\nGOAL VALUE TENSION 0.4 0.6\nL\n;; the end\nL 6\nGOAL NEAR 0 1 2 0.1\n4\n;; closing\n4\n"));
    REQUIRE(answer_field(recording, recording.goals[0]) == "L L 6");
    REQUIRE(answer_field(recording, recording.goals[1]) == "4 4");
    std::string many = "ENTER\nGOAL VALUE TENSION 0.4 0.6\n";
    for (int key = 0; key < 150; ++key)
        many += "L\n";
    const KeyScript long_answer = with_answers_to_next_goal(parsed(many));
    const std::string field = answer_field(long_answer, long_answer.goals[0]);
    // 100 tokens "L" and the space after the last: 200 characters, then the count.
    std::string shown = "L";
    for (int key = 1; key < 100; ++key)
        shown += " L";
    REQUIRE(field == shown + " \u2026 (150 keys)");
}

TEST_CASE("a replayed recording's rows take each goal's verdict and value from its outcome", "[lesson][grade]")
{
    const KeyScript recording = parsed("GOAL VALUE TENSION 0.4 0.6\nL L\nGOAL NEAR 0 1 2 0.1\n4\n"
                                       "GOAL VALUE BIAS -1 1\n");
    GoalProgress reached;
    reached.reached = true;
    reached.value = "+0.45";
    reached.said = "tension +0.45";
    GoalProgress far;
    far.value = "0.35";
    far.said = "the curve passes 0.35 from (0.00, 1.00, 2.00)";
    const std::vector<GoalOutcome> outcomes{{0, GoalOutcome::Verdict::reached, reached, 2},
                                            {1, GoalOutcome::Verdict::not_reached, far, 3}};
    const GradeNames names{"mine.keys", "ex.keys"};
    // Each row says what its goal wants, for the student's feedback (goal_text).
    const std::string tension = "tension within +0.40 to +0.60";
    const std::string near = "the curve within 0.10 of (0.00, 1.00, 2.00)";
    const std::string bias = "bias within -1.00 to +1.00";
    const std::vector<GradeRow> rows = replayed_rows(names, recording, outcomes);
    REQUIRE(rows == std::vector<GradeRow>{
                        {"mine.keys", "ex.keys", "GOAL VALUE TENSION 0.4 0.6", GradeVerdict::yes, "+0.45", "L L", "",
                         tension, "tension +0.45"},
                        {"mine.keys", "ex.keys", "GOAL NEAR 0 1 2 0.1", GradeVerdict::no, "0.35", "4", "", near,
                         "the curve passes 0.35 from (0.00, 1.00, 2.00)"},
                        {"mine.keys", "ex.keys", "GOAL VALUE BIAS -1 1", GradeVerdict::no, "", "", "", bias, ""},
                    });
    REQUIRE(unreplayed_rows(names, recording, GradeVerdict::other) ==
            std::vector<GradeRow>{
                {"mine.keys", "ex.keys", "GOAL VALUE TENSION 0.4 0.6", GradeVerdict::other, "", "", "", tension, ""},
                {"mine.keys", "ex.keys", "GOAL NEAR 0 1 2 0.1", GradeVerdict::other, "", "", "", near, ""},
                {"mine.keys", "ex.keys", "GOAL VALUE BIAS -1 1", GradeVerdict::other, "", "", "", bias, ""},
            });
}
