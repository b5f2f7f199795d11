#include "apcs/formats/key_script.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

using namespace apcs;

namespace {

const std::filesystem::path exercises = std::filesystem::path(APCS_SOURCE_DIR) / "data" / "exercises";
// The answers, apart from the exercises (issue 43): a copy of data/exercises without them is what
// students get.
const std::filesystem::path answers = exercises / "answers";

std::string read_all(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// data/exercises as a teacher hands it out: its files, not answers/.
void copy_exercises(const test::TempFolder& folder)
{
    for (const auto& entry : std::filesystem::directory_iterator(exercises))
        if (entry.is_regular_file())
            std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
}

// The shipped exercises: data/exercises/exercise-*.keys, sorted.
std::vector<std::string> shipped_exercises()
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(exercises)) {
        const std::string name = entry.path().stem().string();
        if (name.starts_with("exercise-") && entry.path().extension() == ".keys")
            names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    return names;
}

test::CommandRun replay(const test::TempFolder& folder, const std::string& script)
{
    return test::run_apcs({"--keys", (folder / script).string(), "--workdir", folder.path().string()});
}

// An answer played from answers/ on the copy in `folder`: its file names are the work folder's.
test::CommandRun replay_answer(const test::TempFolder& folder, const std::string& exercise)
{
    return test::run_apcs(
        {"--keys", (answers / (exercise + "-answer.keys")).string(), "--workdir", folder.path().string()});
}

// `recording` replayed headless on a fresh copy of the exercises ends with exit 0 and writes the
// apcs.log the session that made it wrote in `played`.
void require_recheck_as_played(const std::string& recording, const test::TempFolder& played)
{
    const test::TempFolder fresh;
    copy_exercises(fresh);
    const auto recheck = test::run_apcs({"--keys", recording, "--workdir", fresh.path().string()});
    INFO(recheck.err);
    REQUIRE(recheck.status == 0);
    REQUIRE(read_all(fresh / "apcs.log") == read_all(played / "apcs.log"));
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
        const auto answer = replay_answer(answered, name);
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
    std::string script = read_all(answers / "exercise-1-tension-answer.keys");
    const std::size_t answer = script.find("L L L 6");
    REQUIRE(answer != std::string::npos);
    script.replace(answer, 7, "6 6 6");
    std::ofstream(folder / "wrong.keys", std::ios::binary) << script;
    const auto result = replay(folder, "wrong.keys");
    REQUIRE(result.status == 1);
    REQUIRE(result.err == "apcs: the key script ended at step 4: four-line staff\n" + (folder / "wrong.keys").string() +
                              ":20: goal not reached: tension +0.15, want +0.40 to +0.60\n");
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

namespace {

// Every file of `folder` with its content, to show that a refused run wrote nothing.
std::map<std::string, std::string> folder_content(const test::TempFolder& folder)
{
    std::map<std::string, std::string> content;
    for (const auto& entry : std::filesystem::directory_iterator(folder.path())) {
        const std::filesystem::file_status status = entry.symlink_status();
        std::string& kept = content[entry.path().filename().string()];
        if (std::filesystem::is_symlink(status))
            kept = "link to " + std::filesystem::read_symlink(entry.path()).string();
        else
            kept = std::filesystem::is_regular_file(status) ? read_all(entry.path()) : "not a file";
    }
    return content;
}

} // namespace

TEST_CASE("an exercise refuses the leftovers of an accepted path and headless with no answer is exit 1 on any folder",
          "[cli][exercises][inputs]")
{
    // Issue 43: once a session accepted a path, way1.dat held the answer's tension, and the
    // exercise alone passed with nothing typed. The answer, then the keys that accept the path (a
    // caption ends the answer, so its goal is checked first), leave that folder.
    const test::TempFolder folder;
    copy_exercises(folder);
    const std::string accepted =
        read_all(answers / "exercise-1-tension-answer.keys") + ";; accepted\nENTER ENTER ENTER ENTER N\n";
    const test::TempFolder scripts;
    const auto leftovers = test::run_apcs({"--keys", scripts.write("accept.keys", accepted).string(), "--workdir",
                                           folder.path().string()});
    INFO(leftovers.err);
    REQUIRE(leftovers.status == 0);
    REQUIRE(read_all(folder / "way1.dat") != read_all(exercises / "way1.dat"));
    const auto refused = replay(folder, "exercise-1-tension.keys");
    REQUIRE(refused.status == 1);
    REQUIRE(refused.err.starts_with((folder / "exercise-1-tension.keys").string() +
                                    ":7: way1.dat differs from the exercise's (CRC-32 "));
    REQUIRE(refused.err.ends_with("copy the exercise's files into the work folder again\n"));
    REQUIRE(refused.out.empty());
    const test::TempFolder fresh;
    copy_exercises(fresh);
    const auto unanswered = replay(fresh, "exercise-1-tension.keys");
    REQUIRE(unanswered.status == 1);
    REQUIRE(unanswered.err.find(":17: goal not reached: tension +0.00, want +0.40 to +0.60") != std::string::npos);
    const test::TempFolder answered;
    copy_exercises(answered);
    REQUIRE(replay_answer(answered, "exercise-1-tension").status == 0);
}

TEST_CASE("an exercise whose input is missing or a FIFO or a symbolic link or whose INPUT line is malformed is "
          "refused with exit 1 and writes nothing",
          "[cli][exercises][inputs]")
{
    const test::TempFolder folder;
    copy_exercises(folder);
    const std::string script_name = (folder / "exercise-1-tension.keys").string();
    const std::string again = ": copy the exercise's files into the work folder again\n";
    std::string expected;
    SECTION("a missing input")
    {
        std::filesystem::remove(folder / "key2.dat");
        expected = script_name + ":6: key2.dat is missing from the work folder " + folder.path().string() +
                   "; expected the exercise's input" + again;
    }
    SECTION("a FIFO as an input")
    {
        std::filesystem::remove(folder / "way1.dat");
        REQUIRE(::mkfifo((folder / "way1.dat").c_str(), 0600) == 0);
        expected = script_name + ":7: way1.dat is a FIFO; expected the exercise's input, a regular file of its own" + again;
    }
    SECTION("a symbolic link as an input")
    {
        std::filesystem::remove(folder / "way1.dat");
        std::filesystem::create_symlink(exercises / "way1.dat", folder / "way1.dat");
        expected =
            script_name + ":7: way1.dat is a symbolic link; expected the exercise's input, a regular file of its own" + again;
    }
    SECTION("a bad hex value")
    {
        std::string script = read_all(folder / "exercise-1-tension.keys");
        script.replace(script.find("CRC32 1db7d833"), 14, "CRC32 1db7d8z3");
        folder.write("exercise-1-tension.keys", script);
        expected = script_name + ":7: expected INPUT NAME [CRC32 XXXXXXXX] (XXXXXXXX the CRC-32 of the file's bytes in 8 "
                                 "hex digits); found 'INPUT way1.dat CRC32 1db7d8z3'\n";
    }
    const auto before = folder_content(folder);
    const auto result = replay(folder, "exercise-1-tension.keys");
    REQUIRE(result.status == 1);
    REQUIRE(result.err == expected);
    REQUIRE(result.out.empty());
    REQUIRE(folder_content(folder) == before);
}

TEST_CASE("a recording of every exercise's answer keeps its GOAL and rechecks on fresh inputs and apcs.log says "
          "whether each goal was reached",
          "[cli][exercises][record]")
{
    for (const std::string& name : shipped_exercises()) {
        CAPTURE(name);
        const test::TempFolder answered;
        copy_exercises(answered);
        const test::TempFolder handed_in;
        const std::string recording = (handed_in / "mine.keys").string();
        const auto answer = test::run_apcs({"--keys", (answers / (name + "-answer.keys")).string(), "--workdir",
                                            answered.path().string(), "--record", recording});
        INFO(answer.err);
        REQUIRE(answer.status == 0);
        const std::string recorded = read_all(recording);
        const Expected<KeyScript> exercise = parse_captioned_key_script(read_all(exercises / (name + ".keys")), name);
        REQUIRE(exercise);
        // The exercise's INPUT lines, START and GOAL as the script has them; keys one a line.
        REQUIRE(recorded.starts_with(input_line(exercise->inputs[0]) + "\n"));
        REQUIRE(recorded.find("\nSTART\n") != std::string::npos);
        REQUIRE(recorded.find("\n" + goal_line(exercise->goals[0]) + "\n") != std::string::npos);
        REQUIRE(recorded.find("L L") == std::string::npos);
        REQUIRE(read_all(answered / "apcs.log").find("\ngoal reached: ") != std::string::npos);

        require_recheck_as_played(recording, answered);
    }
    // The exercise alone, recorded, rechecks as not reached: exit 1 and the log says how far off.
    const test::TempFolder bare;
    copy_exercises(bare);
    const test::TempFolder handed_in;
    const auto unanswered = test::run_apcs({"--keys", (bare / "exercise-1-tension.keys").string(), "--workdir",
                                            bare.path().string(), "--record", (handed_in / "mine.keys").string()});
    REQUIRE(unanswered.status == 1);
    REQUIRE(read_all(handed_in / "mine.keys").find("\nGOAL VALUE TENSION 0.4 0.6\n") != std::string::npos);
    REQUIRE(read_all(bare / "apcs.log").find("\ngoal not reached: tension +0.00, want +0.40 to +0.60\n") !=
            std::string::npos);
    const test::TempFolder fresh;
    copy_exercises(fresh);
    REQUIRE(test::run_apcs({"--keys", (handed_in / "mine.keys").string(), "--workdir", fresh.path().string()}).status == 1);
}

TEST_CASE("a recording made with another staff step keeps it on its OPTIONS line and rechecks as it was played",
          "[cli][exercises][record][options]")
{
    const test::TempFolder answered;
    copy_exercises(answered);
    // Five presses of 6 reach tension +0.50 in steps of 0.1, +0.25 in the default 0.05.
    std::string answer = read_all(answers / "exercise-1-tension-answer.keys");
    answer.replace(answer.find("L L L 6"), std::string("L L L 6").size(), "6 6 6 6 6");
    const test::TempFolder handed_in;
    const std::string script = handed_in.write("five.keys", answer).string();
    const std::string recording = (handed_in / "mine.keys").string();
    const auto played = test::run_apcs({"--keys", script, "--workdir", answered.path().string(), "--step", "0.1",
                                        "--glyphs", "ascii", "--record", recording});
    INFO(played.err);
    REQUIRE(played.status == 0);
    const std::string recorded = read_all(recording);
    REQUIRE(recorded.starts_with("INPUT key1.dat CRC32 de215594\nINPUT key2.dat CRC32 b2c6a1da\n"
                                 "INPUT way1.dat CRC32 1db7d833\nOPTIONS --step 0.1\nENTER\n"));

    require_recheck_as_played(recording, answered);
    // The command line's own step wins over the recording's.
    const test::TempFolder other;
    copy_exercises(other);
    const auto stepped = test::run_apcs({"--keys", recording, "--workdir", other.path().string(), "--step", "0.05"});
    REQUIRE(stepped.status == 1);
    REQUIRE(stepped.err.find("mine.keys:16: goal not reached: tension +0.25, want +0.40 to +0.60") != std::string::npos);
}

TEST_CASE("a script whose OPTIONS line names an option a script does not carry is refused before the session",
          "[cli][exercises][options]")
{
    const test::TempFolder folder;
    copy_exercises(folder);
    const std::string script = folder.write("mine.keys", "OPTIONS --png over.png\nENTER\n").string();
    const auto refused = test::run_apcs({"--keys", script, "--workdir", folder.path().string()});
    REQUIRE(refused.status == 1);
    REQUIRE(refused.err.starts_with(script + ":1: OPTIONS --png: not an option a script carries; expected"));
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log"));
    REQUIRE_FALSE(std::filesystem::exists(folder / "over.png"));
}

TEST_CASE("an exercise refuses a command-line option that changes its task and takes one that does not",
          "[cli][exercises][options]")
{
    const test::TempFolder folder;
    copy_exercises(folder);
    const std::string exercise = (folder / "exercise-1-tension.keys").string();
    const auto refused = test::run_apcs({"--keys", exercise, "--workdir", folder.path().string(), "--tension", "0.5"});
    REQUIRE(refused.status == 2);
    REQUIRE(refused.err == "apcs: --tension 0.5: " + exercise +
                               " is an exercise (it has GOAL lines) and this changes its task: apcs grade would "
                               "grade the recording 'other'; expected the exercise's own (only --step, --delay, "
                               "--theta and --phi may differ)\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log"));
    // The same value as the exercise's (the default) is no change; a lesson has no task to keep.
    const auto same = test::run_apcs({"--keys", exercise, "--workdir", folder.path().string(), "--inbetweens", "12",
                                      "--step", "0.1", "--theta", "10"});
    REQUIRE(same.status == 1); // the exercise alone: its goal is not reached
    REQUIRE(same.err.find("goal not reached") != std::string::npos);
}
