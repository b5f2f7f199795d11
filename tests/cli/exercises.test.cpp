#include "apcs/formats/key_event.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;

namespace {

const std::filesystem::path exercises = std::filesystem::path(APCS_SOURCE_DIR) / "data" / "exercises";

std::string read_all(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void copy_exercises(const test::TempFolder& folder)
{
    for (const auto& entry : std::filesystem::directory_iterator(exercises))
        std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
}

// The shipped exercises: data/exercises/exercise-*.keys less the answers, sorted.
std::vector<std::string> shipped_exercises()
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(exercises)) {
        const std::string name = entry.path().stem().string();
        if (name.starts_with("exercise-") && entry.path().extension() == ".keys" && !name.ends_with("-answer"))
            names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

test::CommandRun replay(const test::TempFolder& folder, const std::string& script)
{
    return test::run_apcs({"--keys", (folder / script).string(), "--workdir", folder.path().string()});
}

} // namespace

TEST_CASE("every shipped exercise's answer reaches its goal headless, and the exercise alone does not",
          "[cli][exercises][teaching]")
{
    const std::vector<std::string> names = shipped_exercises();
    REQUIRE(names.size() == 5);
    for (const std::string& name : names) {
        CAPTURE(name);
        const test::TempFolder answered;
        copy_exercises(answered);
        const auto answer = replay(answered, name + "-answer.keys");
        INFO(answer.err);
        REQUIRE(answer.status == 0);
        REQUIRE(answer.err.find("goal not reached") == std::string::npos);
        const test::TempFolder bare;
        copy_exercises(bare);
        const Expected<KeyScript> script = parse_captioned_key_script(read_all(exercises / (name + ".keys")), name);
        REQUIRE(script);
        REQUIRE(script->goals.size() == 1);
        const auto unanswered = replay(bare, name + ".keys");
        REQUIRE(unanswered.status == 1);
        REQUIRE(unanswered.err.find((bare / (name + ".keys")).string() + ":" +
                                    std::to_string(script->goals[0].line_number) + ": goal not reached: ") !=
                std::string::npos);
    }
}

TEST_CASE("a wrong answer to an exercise ends with exit 1 and FILE:LINE: goal not reached, how far off",
          "[cli][exercises]")
{
    const test::TempFolder folder;
    copy_exercises(folder);
    std::string script = read_all(exercises / "exercise-1-tension-answer.keys");
    const std::size_t answer = script.find("L L L 6");
    REQUIRE(answer != std::string::npos);
    script.replace(answer, 7, "6 6 6");
    std::ofstream(folder / "wrong.keys", std::ios::binary) << script;
    const auto result = replay(folder, "wrong.keys");
    REQUIRE(result.status == 1);
    REQUIRE(result.err == "apcs: the key script ended at step 4: four-line staff\n" + (folder / "wrong.keys").string() +
                              ":14: goal not reached: tension +0.15, want +0.40 to +0.60\n");
}

TEST_CASE("a GOAL line's answer is the keys up to the next caption, GOAL line or the end", "[session][exercises]")
{
    const Expected<KeyScript> script = parse_captioned_key_script("ENTER\nGOAL VALUE bias -0.5 0.5 ; kept\n6 6\n"
                                                                  ";; next\n4\nGOAL NEAR 1 2 3 0.5\nGOAL INBETWEEN 2 1 2 3 "
                                                                  "0.25\n4 4\n",
                                                                  "g.keys");
    REQUIRE(script);
    REQUIRE(script->goals.size() == 3);
    REQUIRE(script->goals[0].kind == ScriptGoal::Kind::value);
    REQUIRE(script->goals[0].line == StaffLine::bias);
    REQUIRE(script->goals[0].before_event == 1);
    REQUIRE(script->goals[0].answer_end == 3);
    REQUIRE(script->goals[0].line_number == 2);
    REQUIRE(script->goals[1].before_event == 4);
    REQUIRE(script->goals[1].answer_end == 4);
    REQUIRE(script->goals[2].kind == ScriptGoal::Kind::inbetween);
    REQUIRE(script->goals[2].inbetween == 2);
    REQUIRE(script->goals[2].within == 0.25);
    REQUIRE(script->goals[2].answer_end == 6);
    REQUIRE(goal_text(script->goals[2]) == "in-between 2 within 0.25 of (1.00, 2.00, 3.00)");
}

TEST_CASE("a GOAL line that names no goal is refused with its FILE:LINE", "[session][exercises]")
{
    const auto [line, reason] = GENERATE(table<std::string, std::string>({
        {"GOAL VALUE SPEED 0 1", "a staff line's name and LO <= HI after VALUE"},
        {"GOAL VALUE TENSION 0.6 0.4", "a staff line's name and LO <= HI after VALUE"},
        {"GOAL NEAR 1 2 3 0", "a point X Y Z and a distance D > 0"},
        {"GOAL NEAR 1 2 3", "a point X Y Z and a distance D > 0"},
        {"GOAL INBETWEEN 0 1 2 3 1", "an in-between's number K from 1 to 100000 after INBETWEEN"},
        {"GOAL FAR 1 2 3 1", "a point X Y Z and a distance D > 0"},
        // Issue 45: goals nobody can reach had trapped a paced class.
        {"GOAL VALUE TENSION 2 3", "LO and HI within the staff's -1 to +1"},
        {"GOAL VALUE bias -1.5 0", "LO and HI within the staff's -1 to +1"},
        {"GOAL NEAR 1e200 2 3 1", "X, Y, Z and D of at most 1e9 in size"},
        {"GOAL NEAR 1 2 3 2e9", "X, Y, Z and D of at most 1e9 in size"},
        {"GOAL NEAR 1 2 3 1e-300", "a distance D of at least 0.01 (the feedback's precision)"},
        {"GOAL INBETWEEN 100001 1 2 3 1", "an in-between's number K from 1 to 100000 after INBETWEEN"},
    }));
    const Expected<KeyScript> script = parse_captioned_key_script("ENTER\n" + line + "\n", "g.keys");
    REQUIRE_FALSE(script);
    REQUIRE(script.error().to_string() ==
            "g.keys:2: expected GOAL VALUE NAME LO HI, GOAL NEAR X Y Z D or GOAL INBETWEEN K X Y Z D (" + reason +
                "); found '" + line + "'");
}

TEST_CASE("a GOAL INBETWEEN beyond the session's in-betweens is refused with its FILE:LINE", "[session][exercises]")
{
    const Expected<KeyScript> script =
        parse_captioned_key_script("ENTER\nGOAL INBETWEEN 12 1 2 3 1\nGOAL INBETWEEN 13 1 2 3 1\n", "g.keys");
    REQUIRE(script);
    REQUIRE(goals_within_inbetweens(script->goals, 13, "g.keys"));
    const Expected<void> beyond = goals_within_inbetweens(script->goals, 12, "g.keys");
    REQUIRE_FALSE(beyond);
    REQUIRE(beyond.error().to_string() == "g.keys:3: GOAL INBETWEEN 13 names an in-between beyond the 12 the session "
                                          "makes (--inbetweens 12); expected K from 1 to 12");
}
