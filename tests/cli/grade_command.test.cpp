#include "apcs/cli/grade_command.h"
#include "apcs/cli/session_command.h"
#include "apcs/lesson/grade.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

using namespace apcs;

namespace {

namespace fs = std::filesystem;

const fs::path shipped = fs::path(APCS_SOURCE_DIR) / "data" / "exercises";

const std::string header = "file,exercise,goal,reached,value,keys,options\n";

// data/exercises as a teacher keeps it: the exercises and their inputs in `folder`, the answers
// in `folder`/answers.
void copy_shipped_exercises(const test::TempFolder& folder)
{
    fs::copy(shipped, folder.path(), fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

std::string exercise_of(const test::TempFolder& folder, int number, const std::string& topic)
{
    return (folder / ("exercise-" + std::to_string(number) + "-" + topic + ".keys")).string();
}

std::string answer_of(const test::TempFolder& folder, int number, const std::string& topic)
{
    return (folder.path() / "answers" / ("exercise-" + std::to_string(number) + "-" + topic + "-answer.keys")).string();
}

test::CommandRun grade(std::vector<std::string> files)
{
    files.insert(files.begin(), "grade");
    return test::run_apcs(files);
}

// Every entry under `folder` (its own included): kind, mode, time of last change and, for a file,
// its bytes. A file made and removed again inside a folder changes that folder's time.
std::map<std::string, std::string> snapshot(const fs::path& folder)
{
    std::map<std::string, std::string> entries;
    const auto note = [&entries, &folder](const fs::path& entry) {
        struct stat status {};
        ::lstat(entry.c_str(), &status);
        std::string& kept = entries[fs::relative(entry, folder).string()];
        kept = std::to_string(status.st_mode) + " " + std::to_string(status.st_mtim.tv_sec) + "." +
               std::to_string(status.st_mtim.tv_nsec);
        if (S_ISREG(status.st_mode))
            kept += " " + test::read_all(entry);
    };
    note(folder);
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder))
        note(entry.path());
    return entries;
}

// TMPDIR pointed at a folder of the test's while it lives, so that what grade leaves there is seen.
class TemporaryFolderSetting {
public:
    explicit TemporaryFolderSetting(const fs::path& folder)
    {
        if (const char* old = std::getenv("TMPDIR"))
            m_old = old;
        ::setenv("TMPDIR", folder.c_str(), 1);
    }
    TemporaryFolderSetting(const TemporaryFolderSetting&) = delete;
    TemporaryFolderSetting& operator=(const TemporaryFolderSetting&) = delete;
    ~TemporaryFolderSetting()
    {
        if (m_old)
            ::setenv("TMPDIR", m_old->c_str(), 1);
        else
            ::unsetenv("TMPDIR");
    }

private:
    std::optional<std::string> m_old;
};

// The exercise's text with `answer` after it: a recording whose keys after the GOAL line are `answer`.
std::string recording_of(const std::string& exercise, const std::string& answer)
{
    return test::read_all(exercise) + answer;
}

// `count` staff keys that end where they began (6 then 4), one a line.
std::string staff_keys(int count)
{
    std::string keys;
    for (int key = 0; key < count; ++key)
        keys += key % 2 == 0 ? "6\n" : "4\n";
    return keys;
}

// Exercise 1 as shipped in a folder of its own, its answer, and a folder for what students hand in.
struct TensionExercise {
    test::TempFolder folder;
    std::string exercise;
    std::string right;
    test::TempFolder handed_in;
    std::string goal;
    TensionExercise()
    {
        copy_shipped_exercises(folder);
        exercise = exercise_of(folder, 1, "tension");
        right = answer_of(folder, 1, "tension");
        goal = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,";
    }
    // A recording handed in as `name`, the exercise with `answer` after it.
    std::string hand_in(const std::string& name, const std::string& answer) const
    {
        return handed_in.write(name, recording_of(exercise, answer)).string();
    }
};

// A run of run_grade_command as the command line would make it, with `request` as given.
test::CommandRun grade_request(const GradeRequest& request, const CommonOptions& options = {})
{
    std::ostringstream out;
    std::ostringstream err;
    const ExitStatus status = run_grade_command(request, options, out, err);
    return {static_cast<int>(status), out.str(), err.str()};
}


} // namespace

TEST_CASE("apcs grade under a TMPDIR that is no folder names it", "[cli][grade]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const TemporaryFolderSetting missing(folder / "missing");
    const auto run = test::run_apcs({"grade", exercise_of(folder, 1, "tension"), exercise_of(folder, 1, "tension")});
    REQUIRE(run.status != 0);
    // It said "grade: no temporary folder: No such file or directory".
    REQUIRE(run.err.find("grade: TMPDIR=" + (folder / "missing").string() +
                         " is not a folder to grade in (No such file or directory); set TMPDIR to a folder, or unset "
                         "it for /tmp") != std::string::npos);
}

TEST_CASE("apcs grade prints yes for each recording of the answer and no for the exercise itself",
          "[cli][grade][exercises]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string exercise = exercise_of(folder, 1, "tension");
    const std::string answer = answer_of(folder, 1, "tension");
    const auto result = grade({exercise, answer, answer, exercise});
    INFO(result.err);
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    const std::string goal = ",GOAL VALUE TENSION 0.4 0.6,";
    REQUIRE(result.out == header + answer + "," + exercise + goal + "yes,+0.50,L L L 6,\n" + answer + "," + exercise +
                              goal + "yes,+0.50,L L L 6,\n" + exercise + "," + exercise + goal + "no,+0.00,,\n");
}

TEST_CASE("apcs grade grades every shipped answer yes against its own exercise", "[cli][grade][exercises]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const auto [number, topic] = GENERATE(table<int, std::string>(
        {{1, "tension"}, {2, "continuity"}, {3, "bias"}, {4, "near"}, {5, "inbetween"}}));
    CAPTURE(topic);
    const auto result = grade({exercise_of(folder, number, topic), answer_of(folder, number, topic)});
    INFO(result.err);
    REQUIRE(result.status == 0);
    REQUIRE(result.out.starts_with(header));
    REQUIRE(result.out.find(",yes,") != std::string::npos);
    REQUIRE(result.out.find(",no,") == std::string::npos);
}

TEST_CASE("apcs grade says other for a recording of another exercise and does not replay it", "[cli][grade][exercises]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string exercise = exercise_of(folder, 1, "tension");
    const std::string answer = answer_of(folder, 2, "continuity");
    const auto result = grade({exercise, answer});
    REQUIRE(result.status == 0);
    // Its first departure: the INPUT lines are the same, its GOAL line is not.
    REQUIRE(result.err.starts_with(answer + ":"));
    REQUIRE(result.err.find(": not a recording of " + exercise + ": GOAL VALUE CONTINUITY") != std::string::npos);
    REQUIRE(result.out == header + answer + "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,other,,,\n");
}

TEST_CASE("apcs grade says other for a recording whose INPUT lines differ from the exercise's", "[cli][grade][inputs]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    std::string recording = test::read_all(answer_of(folder, 1, "tension"));
    recording.replace(recording.find("CRC32 1db7d833"), 14, "CRC32 1db7d834");
    const std::string other = folder.write("other-input.keys", recording).string();
    const auto result = grade({exercise_of(folder, 1, "tension"), other});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.ends_with(",other,,,\n"));
}

TEST_CASE("apcs grade gives error rows for a recording that is missing or a FIFO or a folder or garbage",
          "[cli][grade][inputs]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const test::TempFolder handed_in;
    const std::string missing = (handed_in / "missing.keys").string();
    const std::string fifo = (handed_in / "fifo.keys").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const std::string folder_name = (handed_in / "folder.keys").string();
    fs::create_directory(folder_name);
    const std::string garbage = handed_in.write("garbage.keys", "ENTER\nFROBNICATE the staff\n").string();
    const std::string answer = answer_of(folder, 1, "tension");
    const std::string exercise = exercise_of(folder, 1, "tension");
    // The FIFO has no writer: opening it to read would wait for ever.
    const auto result = grade({exercise, missing, fifo, folder_name, garbage, answer});
    REQUIRE(result.status == 1);
    const std::string row_end = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,error,,,\n";
    REQUIRE(result.out == header + missing + row_end + fifo + row_end + folder_name + row_end + garbage + row_end +
                              answer + "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,yes,+0.50,L L L 6,\n");
    REQUIRE(result.err.find(missing + ": ") != std::string::npos);
    REQUIRE(result.err.find(fifo + ": is not a regular file (a FIFO)") != std::string::npos);
    REQUIRE(result.err.find(folder_name + ": ") != std::string::npos);
    REQUIRE(result.err.find(garbage + ":2: ") != std::string::npos);
}

TEST_CASE("apcs grade follows a symbolic link to a recording and grades what it names", "[cli][grade][inputs]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const test::TempFolder handed_in;
    const fs::path link = handed_in / "link.keys";
    fs::create_symlink(answer_of(folder, 1, "tension"), link);
    const auto result = grade({exercise_of(folder, 1, "tension"), link.string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.ends_with(",yes,+0.50,L L L 6,\n"));
    REQUIRE(fs::is_symlink(fs::symlink_status(link)));
}

TEST_CASE("apcs grade refuses with exit 1 an exercise whose input changed or is missing naming it and prints no row",
          "[cli][grade][inputs]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string exercise = exercise_of(folder, 1, "tension");
    std::string expected;
    SECTION("a changed input")
    {
        folder.write("way1.dat", test::read_all(folder / "way1.dat") + "\n");
        expected = exercise + ":7: way1.dat differs from the exercise's (CRC-32 ";
    }
    SECTION("a missing input")
    {
        fs::remove(folder / "key2.dat");
        // The folder beside the exercise, not a work folder: it said "missing from the work folder".
        expected = exercise + ":6: key2.dat is missing from the exercise's folder " + folder.path().string();
    }
    const auto result = grade({exercise, answer_of(folder, 1, "tension")});
    REQUIRE(result.status == 1);
    REQUIRE(result.out.empty());
    REQUIRE(result.err.starts_with(expected));
}

TEST_CASE("apcs grade refuses with exit 1 an exercise with no GOAL line", "[cli][grade][inputs]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string lesson = folder.write("lesson.keys", "INPUT key1.dat CRC32 de215594\nENTER ENTER\n").string();
    const auto result = grade({lesson, answer_of(folder, 1, "tension")});
    REQUIRE(result.status == 1);
    REQUIRE(result.out.empty());
    REQUIRE(result.err == lesson + ": has no GOAL line; apcs grade grades an exercise's goals\n");
}

TEST_CASE("apcs grade leaves the exercise's folder and the recordings' folder and the temporary folder as they were",
          "[cli][grade][exercises]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const test::TempFolder temporary;
    const TemporaryFolderSetting setting(temporary.path());
    const auto before = snapshot(folder.path());
    const auto result = grade({exercise_of(folder, 1, "tension"), answer_of(folder, 1, "tension"),
                               answer_of(folder, 2, "continuity"), exercise_of(folder, 1, "tension")});
    REQUIRE(result.status == 0);
    REQUIRE(snapshot(folder.path()) == before);
    // The private folder was made there, and is gone with everything in it.
    REQUIRE(fs::is_empty(temporary.path()));
}

TEST_CASE("apcs grade quotes a recording's name that holds a comma or a quote as RFC 4180 says", "[cli][grade]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string recording =
        folder.write("Doe, \"Jo\".keys", test::read_all(answer_of(folder, 1, "tension"))).string();
    std::string quoted = "\"";
    for (const char c : recording)
        quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    quoted += '"';
    const std::string exercise = exercise_of(folder, 1, "tension");
    const auto result = grade({exercise, recording});
    REQUIRE(result.status == 0);
    REQUIRE(result.out == header + quoted + "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,yes,+0.50,L L L 6,\n");
}

TEST_CASE("apcs grade writes a field a spreadsheet would run as a formula after an apostrophe",
          "[cli][grade]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    std::string answer = test::read_all(answer_of(folder, 1, "tension"));
    answer.replace(answer.find("L L L 6"), std::string("L L L 6").size(), "=\nTEXT 0.5\nENTER\n");
    const test::TempFolder handed_in;
    handed_in.write("=1+1.keys", answer);
    handed_in.write("@jo.keys", answer);
    const std::string exercise = exercise_of(folder, 1, "tension");
    const fs::path here = fs::current_path();
    fs::current_path(handed_in.path());
    const auto result = grade({exercise, "=1+1.keys", "@jo.keys"});
    fs::current_path(here);
    INFO(result.err);
    REQUIRE(result.status == 0);
    const std::string row = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,yes,+0.50,'= TEXT 0.5 ENTER,\n";
    REQUIRE(result.out == header + "'=1+1.keys" + row + "'@jo.keys" + row);
}

TEST_CASE("apcs grade replays a recording with the options on its OPTIONS line and refuses one naming another option",
          "[cli][grade][options]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    std::string answer = test::read_all(answer_of(folder, 1, "tension"));
    answer.replace(answer.find("L L L 6"), std::string("L L L 6").size(), "6 6 6 6 6");
    const std::string input_lines = "INPUT way1.dat CRC32 1db7d833\n";
    const std::size_t options_at = answer.find(input_lines) + input_lines.size();
    const std::string options_line = std::to_string(
        std::count(answer.begin(), answer.begin() + static_cast<std::ptrdiff_t>(options_at), '\n') + 1);
    const test::TempFolder handed_in;
    const std::string recorded_step =
        handed_in.write("step.keys", std::string(answer).insert(options_at, "OPTIONS --step 0.1\n")).string();
    const std::string default_step = handed_in.write("plain.keys", answer).string();
    const std::string pictures =
        handed_in.write("png.keys", std::string(answer).insert(options_at, "OPTIONS --png /tmp/grade.png\n"))
            .string();
    const std::string exercise = exercise_of(folder, 1, "tension");
    const auto result = grade({exercise, recorded_step, default_step, pictures});
    const std::string goal = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,";
    REQUIRE(result.out == header + recorded_step + goal + "yes,+0.50,6 6 6 6 6,'--step 0.1\n" + default_step + goal +
                              "no,+0.25,6 6 6 6 6,\n" + pictures + goal + "error,,,\n");
    REQUIRE(result.status == 1);
    REQUIRE(result.err.starts_with(pictures + ":" + options_line +
                                   ": OPTIONS --png: not an option a script carries; expected"));
}

TEST_CASE("apcs grade says other for a recording whose OPTIONS set another task than the exercise's",
          "[cli][grade][options]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string input_lines = "INPUT way1.dat CRC32 1db7d833\n";
    // The exercise alone with its staff started at tension +0.50: the goal held with no key typed.
    std::string bare = test::read_all(exercise_of(folder, 1, "tension"));
    bare.insert(bare.find(input_lines) + input_lines.size(), "OPTIONS --tension 0.5\n");
    const test::TempFolder handed_in;
    const std::string started = handed_in.write("started.keys", bare).string();
    const std::string exercise = exercise_of(folder, 1, "tension");
    REQUIRE(grade({exercise, started}).out ==
            header + started + "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,other,,,\n");

    // An exercise that sets its in-between count: a recording made without it is another task.
    std::string six = test::read_all(exercise_of(folder, 5, "inbetween"));
    six.insert(six.find(input_lines) + input_lines.size(), "OPTIONS --inbetweens 6\n");
    const std::string sixes = folder.write("six.keys", six).string();
    const std::string answer = answer_of(folder, 5, "inbetween");
    std::string answer_six = test::read_all(answer);
    answer_six.insert(answer_six.find(input_lines) + input_lines.size(), "OPTIONS --inbetweens 6 --step 0.1\n");
    const std::string with_six = handed_in.write("with-six.keys", answer_six).string();
    const auto result = grade({sixes, answer, with_six});
    INFO(result.err);
    REQUIRE(result.status == 0);
    const std::vector<std::string> rows = [&result] {
        std::vector<std::string> lines;
        std::istringstream text(result.out);
        for (std::string line; std::getline(text, line);)
            lines.push_back(line);
        return lines;
    }();
    REQUIRE(rows.size() == 3);
    CHECK(rows[1].starts_with(answer + "," + sixes + ",GOAL INBETWEEN 1 0.31 -0.41 0.47 0.1,other,"));
    // The staff step may differ: the recording with the exercise's in-betweens is replayed.
    CHECK(rows[2].starts_with(with_six + "," + sixes + ",GOAL INBETWEEN 1 0.31 -0.41 0.47 0.1,"));
    CHECK(rows[2].find(",other,") == std::string::npos);
}

TEST_CASE("apcs grade says no for a goal that can never be met", "[cli][grade][exercises]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const auto far_away = [](std::string script) {
        script.replace(script.find("GOAL VALUE TENSION 0.40 0.60"), 28, "GOAL NEAR 1e8 1e8 1e8 0.01");
        return script;
    };
    const std::string exercise =
        folder.write("far.keys", far_away(test::read_all(exercise_of(folder, 1, "tension")))).string();
    const std::string recording =
        folder.write("far-answer.keys", far_away(test::read_all(answer_of(folder, 1, "tension")))).string();
    const auto result = grade({exercise, recording, exercise});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.find(recording + "," + exercise + ",GOAL NEAR 1e+08 1e+08 1e+08 0.01,no,") !=
            std::string::npos);
    REQUIRE(result.out.find(",yes,") == std::string::npos);
}

TEST_CASE("apcs grade judges a goal on its path as the student accepted it: a value set on the second path, or "
          "reached and left before the accept, grades no with the value accepted",
          "[cli][grade][exercises][verdict]")
{
    // Issue 57 item 2 (SPEC 3.2). `at_goal` after the exercise's GOAL line, `afterwards` after its
    // closing caption, where a student's keys typed once the replay went on stand.
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const test::TempFolder handed_in;
    const auto recording = [&](int number, const std::string& topic, const std::string& at_goal,
                               const std::string& afterwards) {
        std::string text = test::read_all(exercise_of(folder, number, topic));
        const std::size_t goal_line_end = text.find('\n', text.find("\nGOAL ") + 1);
        text.insert(goal_line_end + 1, at_goal + "\n");
        return handed_in.write(topic + ".keys", text + afterwards + "\n").string();
    };
    // A real exercise-3 session: way1.dat accepted unchanged, then BIAS +0.30 on ani4.dat.
    const std::string bias = exercise_of(folder, 3, "bias");
    const std::string other_path = recording(3, "bias", "ENTER ENTER N Y ENTER ENTER 8 ENTER ENTER L L", "");
    const auto graded_bias = grade({bias, other_path});
    INFO(graded_bias.err);
    REQUIRE(graded_bias.status == 0);
    CHECK(graded_bias.out == header + other_path + "," + bias +
                                 ",GOAL VALUE BIAS 0.3 0.5,no,+0.00,ENTER ENTER N Y ENTER ENTER 8 ENTER ENTER L L,\n");
    // Continuity -0.45 reached at the goal, then moved back to -0.15 and accepted.
    const std::string continuity = exercise_of(folder, 2, "continuity");
    const std::string left = recording(2, "continuity", "J J J", "L L ENTER ENTER ENTER N");
    const auto graded_continuity = grade({continuity, left});
    REQUIRE(graded_continuity.status == 0);
    CHECK(graded_continuity.out.starts_with(header + left + "," + continuity +
                                            ",GOAL VALUE CONTINUITY -0.6 -0.4,no,-0.15,"));
}

TEST_CASE("apcs grade needs an exercise and at least one recording and its help shows a runnable example",
          "[cli][grade]")
{
    const auto none = test::run_apcs({"grade"});
    REQUIRE(none.status == 2);
    REQUIRE(none.out.empty());
    const auto exercise_only = test::run_apcs({"grade", (shipped / "exercise-1-tension.keys").string()});
    REQUIRE(exercise_only.status == 2);
    const auto help = test::run_apcs({"grade", "--help"});
    REQUIRE(help.status == 0);
    REQUIRE(help.out.find("apcs grade data/exercises/exercise-1-tension.keys "
                          "data/exercises/answers/exercise-1-tension-answer.keys") != std::string::npos);
}

TEST_CASE("apcs grade says other for an answer moved above the GOAL line or into the preamble, and names the line",
          "[cli][grade][issue57]")
{
    const TensionExercise one;
    const std::string& exercise = one.exercise;
    const std::string text = test::read_all(exercise);
    const test::TempFolder& handed_in = one.handed_in;
    // sed 's/^8$/8 L L L/' exercise-1-tension.keys: the answer before the GOAL line.
    std::string above = text;
    above.replace(above.find("\n8\n"), 3, "\n8 L L L\n");
    const std::string moved = handed_in.write("moved.keys", above).string();
    // The answer among the opening prompts' keys, decoys after the GOAL.
    std::string preamble = text;
    preamble.replace(preamble.find("ENTER ENTER\nTEXT 0 90 100"), 25, "ENTER ENTER\nTEXT 0 90 100\nL L L");
    preamble += "6 4\n";
    const std::string decoy = handed_in.write("decoy.keys", preamble).string();
    const auto result = grade({exercise, moved, decoy});
    INFO(result.err);
    REQUIRE(result.status == 0);
    const std::string goal = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,";
    REQUIRE(result.out == header + moved + goal + "other,,,\n" + decoy + goal + "other,,,\n");
    const auto line_of = [](const std::string& script, const std::string& what) {
        return std::to_string(std::count(script.begin(), script.begin() + static_cast<std::ptrdiff_t>(script.find(what)),
                                         '\n') + 1);
    };
    REQUIRE(result.err.find(moved + ":" + line_of(above, "8 L L L") + ": not a recording of " + exercise + ": 'L' where " +
                            exercise + ":") != std::string::npos);
    REQUIRE(result.err.find(decoy + ":" + line_of(preamble, "L L L") + ": not a recording of " + exercise + ": 'L' where ") !=
            std::string::npos);
}

TEST_CASE("apcs grade takes the keys after the closing caption as the answer, a BOM and tabs as any script has them, "
          "and a blank recording as nothing done",
          "[cli][grade][issue57]")
{
    const TensionExercise one;
    const std::string& exercise = one.exercise;
    const std::string text = test::read_all(exercise);
    const test::TempFolder& handed_in = one.handed_in;
    // As --record writes it once the replay moved on: the student's keys after the closing caption.
    const std::string after = handed_in.write("after.keys", text + "L\nL\nL\n6\n").string();
    std::string tabbed = "\xEF\xBB\xBF" + text + "L\tL L\t6\n";
    tabbed.replace(tabbed.find("ENTER ENTER\nTEXT"), 11, "ENTER\tENTER");
    const std::string bom = handed_in.write("bom.keys", tabbed).string();
    const std::string blank = handed_in.write("blank.keys", "; handed in empty\n\n").string();
    const std::string empty = handed_in.write("empty.keys", "").string();
    const auto result = grade({exercise, after, bom, blank, empty});
    INFO(result.err);
    REQUIRE(result.status == 0);
    const std::string goal = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,";
    REQUIRE(result.out == header + after + goal + "yes,+0.50,L L L 6,\n" + bom + goal + "yes,+0.50,L L L 6,\n" + blank +
                              goal + "no,,,\n" + empty + goal + "no,,,\n");
}

TEST_CASE("apcs grade gives a recording of more than 100,000 keys an error row, too long, and cuts a long answer's "
          "keys at 200 characters",
          "[cli][grade][issue57]")
{
    const TensionExercise one;
    const std::string& exercise = one.exercise;
    const std::string text = test::read_all(exercise);
    const test::TempFolder& handed_in = one.handed_in;
    // The exercise's 22 keys and 99,979 more: 100,001.
    std::string many = text;
    for (int key = 0; key < 99'979; ++key)
        many += "L\n";
    const std::string too_long = handed_in.write("too-long.keys", many).string();
    // 300 keys: L and 6 in turn end where they began, then the answer's L L L 6.
    std::string long_text = text;
    for (int key = 0; key < 148; ++key)
        long_text += key % 2 == 0 ? "L\n" : "J\n";
    long_text += "L L L 6\n";
    const std::string long_answer = handed_in.write("long.keys", long_text).string();
    const auto result = grade({exercise, too_long, long_answer});
    INFO(result.err);
    REQUIRE(result.status == 1);
    const std::string goal = "," + exercise + ",GOAL VALUE TENSION 0.4 0.6,";
    // Refused at the line of its 100,001st key, read no further.
    const auto last_line = std::to_string(std::count(text.begin(), text.end(), '\n') + 99'979);
    REQUIRE(result.err.find(too_long + ":" + last_line + ": too long: more than 100000 keys, at most 100000 are read") !=
            std::string::npos);
    std::string shown = "L";
    for (int key = 1; key < 100; ++key)
        shown += key % 2 == 0 ? " L" : " J";
    REQUIRE(result.out == header + too_long + goal + "error,,,\n" + long_answer + goal + "yes,+0.50," + shown +
                              " \u2026 (152 keys),\n");
}


TEST_CASE("A replay's work is one operation a key and one more for each control point of the largest path",
          "[cli][grade][issue57]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string exercise = exercise_of(folder, 1, "tension");
    const auto work_of = [&](const std::string& answer) {
        const test::TempFolder work;
        for (const char* input : {"key1.dat", "key2.dat", "way1.dat"})
            fs::copy_file(folder / input, work / input);
        const Expected<KeyScript> script = parse_captioned_key_script(recording_of(exercise, answer), "r.keys");
        REQUIRE(script);
        std::ostream unheard(nullptr);
        return replay_in_folder(*script, "r.keys", {}, work.path(), unheard).work_done;
    };
    // On the staff of way1.dat (3 control points) each key costs 1 + 3.
    const std::uint64_t answered = work_of("L L L 6\n");
    REQUIRE(work_of(staff_keys(100) + "L L L 6\n") == answered + 100 * 4);
    // Each point inserted makes every later key cost one more. I costs two of the curve's blocks
    // (64 segments each on a short path) and a 64th of the points: 1 + 128 + 0; then Enter leaves
    // the waypoint editor (on 4 points: 5) and the 8 and the answer's 4 keys cost 5 each.
    const std::string shape_again = "ENTER ENTER ENTER ENTER Y W ";
    const std::uint64_t unchanged = work_of(shape_again + "ENTER 8 L L L 6\n");
    REQUIRE(work_of(shape_again + "I ENTER 8 L L L 6\n") == unchanged + 129 + 6 * 1);
    // An insert costs what its block does, not the path: 16,000 on way1.dat stay within the budget
    // (issue 61: each had cost the whole path, and the replay was stopped at about 4,900).
    std::string inserts;
    for (int i = 0; i < 16'000; ++i)
        inserts += "I ";
    const std::uint64_t many = work_of(shape_again + inserts + "ENTER 8 L L L 6\n");
    CAPTURE(many);
    REQUIRE(many < most_replay_operations);
}

TEST_CASE("apcs grade stops a replay past its work budget: an error row, too long, and grades the recordings after it",
          "[cli][grade][issue57]")
{
    const TensionExercise one;
    const std::string busy = one.hand_in("busy.keys", staff_keys(600) + "L L L 6\n");
    GradeRequest request{one.exercise, {busy, one.right}};
    request.work_budget = 2'000; // the 600 staff keys alone cost 2,400; the answer costs less than 200
    const auto result = grade_request(request);
    INFO(result.err);
    REQUIRE(result.status == 1);
    REQUIRE(result.out == header + busy + one.goal + "error,,,\n" + one.right + one.goal + "yes,+0.50,L L L 6,\n");
    REQUIRE(result.err == busy + ": too long: its keys cost more than 2000 operations, the work budget of a replay\n");
    // The budget as shipped lets it through.
    request.work_budget = most_replay_operations;
    REQUIRE(grade_request(request).status == 0);
}

TEST_CASE("apcs grade replays no recording that would need more memory than APCS_MEMORY_LIMIT leaves for replays",
          "[cli][grade][issue57]")
{
    const TensionExercise one;
    // 4 MiB a replay and 320 bytes a key: 5,026 keys (the exercise's and 5,004) need 5.5 MiB; the
    // answer's 50 keys 4 MiB.
    const std::string busy = one.hand_in("busy.keys", staff_keys(5'000) + "L L L 6\n");
    CommonOptions options;
    options.memory_limit = grade_own_bytes + (std::uint64_t{5} << 20);
    const auto result = grade_request({one.exercise, {busy, one.right}}, options);
    INFO(result.err);
    REQUIRE(result.status == 1);
    REQUIRE(result.out == header + busy + one.goal + "error,,,\n" + one.right + one.goal + "yes,+0.50,L L L 6,\n");
    REQUIRE(result.err.starts_with(busy + ": too long: its 5"));
    REQUIRE(result.err.ends_with(" keys need about 5.5 MiB to replay, and apcs grade has 5 MiB for replays "
                                 "(100 MB, or APCS_MEMORY_LIMIT when lower, less 24 MiB for itself)\n"));
    // A limit below what grade keeps for itself leaves nothing for replays: every row an error.
    options.memory_limit = grade_own_bytes;
    REQUIRE(grade_request({one.exercise, {one.right}}, options).out == header + one.right + one.goal + "error,,,\n");
}

TEST_CASE("apcs grade prints the rows in the order given whichever replay ends first", "[cli][grade][issue57]")
{
    const TensionExercise one;
    std::vector<std::string> files{one.exercise};
    std::string expected = header;
    for (int index = 0; index < 12; ++index) {
        // Every third a long replay (2,000 keys before the answer), the others at once.
        const bool slow = index % 3 == 0;
        const bool right = index % 2 == 0;
        const std::string answer = (slow ? staff_keys(2'000) : std::string()) + (right ? "L L L 6\n" : "6\n");
        files.push_back(one.hand_in("r" + std::to_string(index) + ".keys", answer));
        std::string keys = right ? "L L L 6" : "6";
        if (slow) {
            // The answer's first 100 keys (6 4 6 4 …, 199 characters), then how many in all.
            keys = "6";
            for (int key = 1; key < 100; ++key)
                keys += key % 2 == 0 ? " 6" : " 4";
            keys += right ? " \u2026 (2004 keys)" : " \u2026 (2001 keys)";
        }
        expected += files.back() + one.goal + (right ? "yes,+0.50," : "no,+0.05,") + keys + ",\n";
    }
    const auto result = grade(files);
    INFO(result.err);
    REQUIRE(result.status == 0);
    REQUIRE(result.out == expected);
}

TEST_CASE("apcs grade --class prints a gradebook, a row per student folder, and --feedback writes each student's "
          "sheet",
          "[cli][grade][issue57]")
{
    const test::TempFolder folder;
    copy_shipped_exercises(folder);
    const std::string tension = exercise_of(folder, 1, "tension");
    const std::string continuity = exercise_of(folder, 2, "continuity");
    const test::TempFolder room;
    const fs::path class_folder = room / "class";
    for (const char* student : {"alice", "bob", "carol", "dave", ".hidden"})
        fs::create_directories(class_folder / student);
    room.write("class/notes.txt", "not a student");
    // alice hands in both answers; bob the same keys (comments and layout aside); carol the tension
    // exercise untouched and the tension answer under the continuity exercise's name; dave nothing.
    fs::copy_file(answer_of(folder, 1, "tension"), class_folder / "alice" / "exercise-1-tension.keys");
    fs::copy_file(answer_of(folder, 2, "continuity"), class_folder / "alice" / "exercise-2-continuity.keys");
    room.write("class/bob/exercise-1-tension.keys", recording_of(tension, "; mine\nL\nL  L\n6\n"));
    room.write("class/bob/exercise-2-continuity.keys", test::read_all(class_folder / "alice" / "exercise-2-continuity.keys"));
    fs::copy_file(tension, class_folder / "carol" / "exercise-1-tension.keys");
    fs::copy_file(answer_of(folder, 1, "tension"), class_folder / "carol" / "exercise-2-continuity.keys");
    const fs::path returned = room / "returned";
    const auto result = test::run_apcs({"grade", "--class", class_folder.string(), "--feedback", returned.string(),
                                        tension, continuity});
    INFO(result.err);
    REQUIRE(result.status == 0);
    REQUIRE(result.out == "student,exercise-1-tension:1,exercise-2-continuity:1,reached,of,same_as\n"
                          "alice,yes,yes,2,2,bob\n"
                          "bob,yes,yes,2,2,alice\n"
                          "carol,no,other,0,2,\n"
                          "dave,missing,missing,0,2,\n");
    const std::string carol_other = (class_folder / "carol" / "exercise-2-continuity.keys").string();
    REQUIRE(result.err.starts_with(carol_other + ":20: not a recording of " + continuity + ": GOAL VALUE TENSION"));
    std::vector<std::string> sheets;
    for (const fs::directory_entry& entry : fs::directory_iterator(returned))
        sheets.push_back(entry.path().filename().string());
    std::ranges::sort(sheets);
    REQUIRE(sheets == std::vector<std::string>{"alice.txt", "bob.txt", "carol.txt", "dave.txt"});
    REQUIRE(test::read_all(returned / "alice.txt") ==
            "Feedback for alice: 2 of 2 goals reached.\n"
            "\nexercise-1-tension\n"
            "  goal 1: reached, tension +0.50\n    wanted: tension within +0.40 to +0.60\n"
            "\nexercise-2-continuity\n"
            "  goal 1: reached, continuity -0.50\n    wanted: continuity within -0.60 to -0.40\n");
    const std::string carol = test::read_all(returned / "carol.txt");
    REQUIRE(carol.starts_with("Feedback for carol: 0 of 2 goals reached.\n"
                              "\nexercise-1-tension\n"
                              "  goal 1: not reached, tension +0.00\n    wanted: tension within +0.40 to +0.60\n"
                              "\nexercise-2-continuity\n  " +
                              carol_other + ":20:"));
    // The reason follows, wrapped at 79 columns (its words hold the test's folders).
    REQUIRE(carol.find("not a recording of") != std::string::npos);
    REQUIRE(carol.ends_with("  goal 1: not graded: the recording is not of this exercise\n"
                            "    wanted: continuity within -0.60 to -0.40\n"));
    REQUIRE(test::read_all(returned / "dave.txt") ==
            "Feedback for dave: 0 of 2 goals reached.\n"
            "\nexercise-1-tension: no recording handed in\n"
            "  goal 1: not handed in\n    wanted: tension within +0.40 to +0.60\n"
            "\nexercise-2-continuity: no recording handed in\n"
            "  goal 1: not handed in\n    wanted: continuity within -0.60 to -0.40\n");
}

TEST_CASE("apcs grade --class refuses a class folder it cannot read, and --feedback without --class",
          "[cli][grade][issue57]")
{
    const std::string tension = (shipped / "exercise-1-tension.keys").string();
    const test::TempFolder room;
    const auto missing = test::run_apcs({"grade", "--class", (room / "nobody").string(), tension});
    REQUIRE(missing.status == 1);
    REQUIRE(missing.out.empty());
    REQUIRE(missing.err.starts_with((room / "nobody").string() + ": cannot read the class folder: "));
    const auto alone = test::run_apcs({"grade", "--feedback", room.path().string(), tension, tension});
    REQUIRE(alone.status == 2);
    REQUIRE(alone.out.empty());
    // Two exercises of one file name would read the same recording of each student.
    fs::create_directories(room / "class" / "jo");
    const test::TempFolder other;
    fs::copy_file(tension, other / "exercise-1-tension.keys");
    const auto twice = test::run_apcs({"grade", "--class", (room / "class").string(), tension,
                                       (other / "exercise-1-tension.keys").string()});
    REQUIRE(twice.status == 2);
    REQUIRE(twice.out.empty());
    REQUIRE(twice.err.find("have one file name") != std::string::npos);
    // Sheets written into the class folder would be a student at the next grade.
    const auto within = test::run_apcs(
        {"grade", "--class", (room / "class").string(), "--feedback", (room / "class" / "returned").string(), tension});
    REQUIRE(within.status == 2);
    REQUIRE(within.err.find("is inside the class folder") != std::string::npos);
    REQUIRE_FALSE(fs::exists(room / "class" / "returned"));
}

TEST_CASE("apcs grade --class gives a student whose folder is a link to nothing error cells, and an empty class a "
          "header",
          "[cli][grade][issue57]")
{
    const std::string tension = (shipped / "exercise-1-tension.keys").string();
    const test::TempFolder room;
    fs::create_directories(room / "empty");
    const auto empty = test::run_apcs({"grade", "--class", (room / "empty").string(), tension});
    REQUIRE(empty.status == 0);
    REQUIRE(empty.out == "student,exercise-1-tension:1,reached,of,same_as\n");
    fs::create_directories(room / "class");
    fs::create_directory_symlink(room / "nowhere", room / "class" / "dave");
    const auto dangling = test::run_apcs({"grade", "--class", (room / "class").string(), tension});
    REQUIRE(dangling.status == 1);
    REQUIRE(dangling.out == "student,exercise-1-tension:1,reached,of,same_as\ndave,error,0,1,\n");
    REQUIRE(dangling.err.starts_with((room / "class" / "dave").string() + ": a link to no folder"));
}
