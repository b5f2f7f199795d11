#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"
#include "apcs/cli/session_command.h"
#include "apcs/formats/key_script.h"
#include "apcs/lesson/replay_pace.h"
#include "apcs/lesson/handout.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/screens/replay_caption.h"
#include "apcs/session/session_files.h"

#include "support/golden.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <utility>

using namespace apcs;

namespace {

// A copy of a bundled example, so that the session's writes do not touch data/.
void copy_example(const std::string& example, const test::TempFolder& folder)
{
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "data" / example))
        std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
}

} // namespace

TEST_CASE("the N to L session replays headless to its approved screens and files", "[session][headless]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    const auto result = test::run_apcs({"--keys", (folder / "session.keys").string(), "--workdir",
                                        folder.path().string(), "--glyphs", "ascii"});
    REQUIRE(result.err.empty());
    REQUIRE(result.status == 0);
    test::check_golden("n-to-l/screens.txt", result.out);
    for (const char* name : {"way1.dat", "way4.dat", "inb001.dat", "inb006.dat", "inb012.dat", "ani2.dat"})
        test::check_golden(std::string("n-to-l/") + name, test::read_all(folder / name));
    REQUIRE(std::filesystem::exists(folder / "way1.bak"));
    REQUIRE_FALSE(std::filesystem::exists(folder / "inb013.dat"));
}

TEST_CASE("a recorded session replays to the same files", "[session][headless]")
{
    const test::TempFolder first;
    const test::TempFolder second;
    copy_example("n-to-l", first);
    copy_example("n-to-l", second);
    const auto recorded = test::run_apcs({"--keys", (first / "session.keys").string(), "--workdir",
                                          first.path().string(), "--record", (first / "again.keys").string()});
    REQUIRE(recorded.status == 0);
    const auto replayed = test::run_apcs({"--keys", (first / "again.keys").string(), "--workdir", second.path().string()});
    REQUIRE(replayed.status == 0);
    // --record keeps the keys and the script's captions: the screens and captions are the same.
    REQUIRE(replayed.out == recorded.out);
    for (const char* name : {"way1.dat", "way4.dat", "inb007.dat", "apcs.log"})
        REQUIRE(test::read_all(first / name) == test::read_all(second / name));
}

TEST_CASE("without a terminal and without --keys the session refuses with exit 3", "[session][headless]")
{
    const test::TempFolder folder;
    const auto result = test::run_apcs({"--workdir", folder.path().string()});
    REQUIRE(result.status == 3);
    REQUIRE_FALSE(std::filesystem::exists(folder / "apcs.log")); // nothing written when nothing runs
    REQUIRE(result.err == "apcs: standard input is not a terminal; give --keys FILE to replay a session without one\n");
}

TEST_CASE("a bad key script is exit 1 with FILE:LINE", "[session][headless]")
{
    const test::TempFolder folder;
    const auto script = folder.write("bad.keys", "ENTER\nF2\n");
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 1);
    REQUIRE(result.err.starts_with(script.string() + ":2: expected a single printable character"));
}

TEST_CASE("a script that ends early says at which step", "[session][headless]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    const auto script = folder.write("short.keys", "ENTER\n");
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.err == "apcs: the key script ended at step 1: KEY2 file\n");
}

namespace {

// The N to L session with the answers at the KEY1 and first path prompts replaced.
std::string n_to_l_script(const std::string& key1_answer, const std::string& first_path)
{
    std::string script = test::read_all(std::filesystem::path(APCS_SOURCE_DIR) / "data/n-to-l/session.keys");
    // The session's own inputs are not this script's: it reads the files named here.
    for (std::size_t input = script.find("INPUT "); input != std::string::npos; input = script.find("INPUT "))
        script.erase(input, script.find('\n', input) + 1 - input);
    const std::string first_key = "ENTER            ; KEY1: key1.dat";
    script.replace(script.find(first_key), first_key.size(), "TEXT " + key1_answer + "\nENTER");
    script.replace(script.find("TEXT way1.dat"), std::string("TEXT way1.dat").size(), "TEXT " + first_path);
    return script;
}

} // namespace

TEST_CASE("a path file typed in another case is rewritten as the file that was read", "[session][headless][files]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    const std::string original = test::read_all(folder / "way1.dat");
    const auto script = folder.write("upper.keys", n_to_l_script("key1.dat", "WAY1.DAT"));
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 0);
    REQUIRE_FALSE(std::filesystem::exists(folder / "WAY1.DAT"));
    REQUIRE(test::read_all(folder / "way1.dat") != original);
    REQUIRE(test::read_all(folder / "way1.bak") == original);
}

TEST_CASE("a key file named by its absolute path is never overwritten by surface fitting", "[session][headless][files]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    // KEY1 is a file that surface fitting would write: inb001.dat, named absolutely.
    std::filesystem::copy_file(folder / "key1.dat", folder / "inb001.dat");
    const std::string key = test::read_all(folder / "inb001.dat");
    const auto script = folder.write("abs.keys", n_to_l_script((folder / "inb001.dat").string(), "way1.dat"));
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(test::read_all(folder / "inb001.dat") == key);
    REQUIRE(result.out.find("inb001.dat: is a key file; key files are never written") != std::string::npos);
    // Headless, nobody saw the message: the run fails with it.
    REQUIRE(result.status == 1);
    REQUIRE(result.err.find("apcs: inb001.dat: is a key file; key files are never written\n") != std::string::npos);
}

TEST_CASE("a --record script never replaces a key file", "[session][headless][files]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    const std::string key = test::read_all(folder / "key1.dat");
    const auto result = test::run_apcs({"--keys", (folder / "session.keys").string(), "--workdir",
                                        folder.path().string(), "--record", (folder / "KEY1.DAT").string()});
    REQUIRE(result.status == 1);
    REQUIRE(result.err.find("is a key file; key files are never written") != std::string::npos);
    REQUIRE(test::read_all(folder / "key1.dat") == key);
    REQUIRE_FALSE(std::filesystem::exists(folder / "KEY1.DAT"));
}

TEST_CASE("a path file reached through a symbolic link out of the work folder is refused", "[session][headless][files]")
{
    const test::TempFolder outside;
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    std::filesystem::copy_file(folder / "way1.dat", outside / "way1.dat");
    std::filesystem::create_directory_symlink(outside.path(), folder / "out");
    const std::string original = test::read_all(outside / "way1.dat");
    const auto script = folder.write("link.keys", n_to_l_script("key1.dat", "out/way1.dat"));
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.out.find("out/way1.dat: expected a file in the session's folder") != std::string::npos);
    REQUIRE(test::read_all(outside / "way1.dat") == original);
    REQUIRE_FALSE(std::filesystem::exists(outside / "way1.bak"));
}

TEST_CASE("a key named like the .bak of a file the session rewrites is never replaced by that backup",
          "[session][headless][files]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    // KEY1 is ani1.bak; an older ani1.dat is there, which the split rewrites.
    std::filesystem::rename(folder / "key1.dat", folder / "ani1.bak");
    folder.write("ani1.dat", "0 0 0\n0 0 1\n");
    const std::string key = test::read_all(folder / "ani1.bak");
    const auto script = folder.write("bak.keys", n_to_l_script("ani1.bak", "way1.dat"));
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 0);
    REQUIRE(test::read_all(folder / "ani1.bak") == key);
    REQUIRE(test::read_all(folder / "ani1.b01") == "0 0 0\n0 0 1\n");
    REQUIRE(test::read_all(folder / "apcs.log").find("kept the old ani1.dat as ani1.b01, since its .bak is a key file") !=
            std::string::npos);
}

TEST_CASE("the shipped sessions walk a class through the thesis' six steps in captions that fit the message line",
          "[session][headless][captions]")
{
    // Every shipped session walks through all six steps (SPEC §3), each named in a caption.
    const std::pair<const char*, const char*> examples[] = {
        {"n-to-l", "123456"}, {"stick", "123456"}, {"snake-apple", "123456"}};
    for (const auto& [example, expected_steps] : examples) {
        const std::filesystem::path keys = std::filesystem::path(APCS_SOURCE_DIR) / "data" / example / "session.keys";
        std::ifstream file(keys);
        std::stringstream text;
        text << file.rdbuf();
        const Expected<KeyScript> script = parse_captioned_key_script(text.str(), keys.string());
        REQUIRE(script);
        std::string steps;
        for (const ScriptCaption& caption : script->captions) {
            INFO(example << ": " << caption.text);
            REQUIRE(caption.text.size() <= 78);
            REQUIRE(caption.text.starts_with("Step "));
            if (steps.find(caption.text[5]) == std::string::npos)
                steps += caption.text[5];
        }
        std::sort(steps.begin(), steps.end());
        CAPTURE(example);
        REQUIRE(steps == expected_steps);
    }
}

TEST_CASE("the N to L lesson (T, G, =, W, U) replays headless to its approved screens in each glyph set",
          "[session][headless][teaching]")
{
    for (const char* glyphs : {"ascii", "braille", "blocks"}) {
        const test::TempFolder folder;
        copy_example("n-to-l", folder);
        const auto result = test::run_apcs({"--keys", (folder / "lesson.keys").string(), "--workdir",
                                            folder.path().string(), "--glyphs", glyphs});
        REQUIRE(result.status == 0);
        REQUIRE(result.err == "apcs: the key script ended at step 5: next path\n");
        test::check_golden(std::string("lesson/screens-") + glyphs + ".txt", result.out);
        // The waypoint inserted and moved 12 steps left is in the file, with the typed staff values.
        test::check_golden("lesson/ani1.dat", test::read_all(folder / "ani1.dat"));
    }
}

namespace {

// The shipped lessons: every data/EXAMPLE/lesson*.keys, as "EXAMPLE/FILE".
std::vector<std::string> shipped_lessons()
{
    std::vector<std::string> lessons;
    const std::filesystem::path data = std::filesystem::path(APCS_SOURCE_DIR) / "data";
    for (const auto& example : std::filesystem::directory_iterator(data))
        if (example.is_directory())
            for (const auto& file : std::filesystem::directory_iterator(example.path()))
                if (file.path().filename().string().starts_with("lesson") && file.path().extension() == ".keys")
                    lessons.push_back(example.path().filename().string() + "/" + file.path().filename().string());
    std::sort(lessons.begin(), lessons.end());
    return lessons;
}

KeyScript read_lesson(const std::string& lesson)
{
    const std::filesystem::path file = std::filesystem::path(APCS_SOURCE_DIR) / "data" / lesson;
    const Expected<KeyScript> script = parse_captioned_key_script(test::read_all(file), file.string());
    INFO((script ? std::string() : script.error().to_string()));
    REQUIRE(script);
    return *script;
}

// Each caption of `lesson` beside the screen its keys made, as PgDn shows it and the handout prints
// it (SPEC 3.2), at 80x24 in `glyphs`: "=== N: CAPTION", then the screen with the caption on its
// last row (trailing blanks removed).
std::string caption_screens(const std::string& lesson, GlyphSet glyphs)
{
    const std::filesystem::path example = std::filesystem::path(lesson).parent_path();
    const test::TempFolder folder;
    copy_example(example.string(), folder);
    FolderFiles files(folder.path());
    Session session({}, files);
    std::string screens;
    int number = 0;
    std::ostream no_screens(nullptr);
    const KeyScript script = read_lesson(lesson);
    ReplayHooks hooks;
    hooks.caption_ended = [&](std::size_t index, const std::string&, const ProgramScreen& shown,
                             const std::vector<std::string>&) {
        screens += "=== " + std::to_string(++number) + ": " + script.captions[index].text + "\n";
        screens += screen_text(with_caption(shown, script.captions[index].text), glyphs);
    };
    ReplayDriver replay(session, script, lesson, ReplayPace{}, hooks, ReplayAudience::headless);
    run_headless_session(replay, session, glyphs, no_screens);
    return screens;
}

} // namespace

TEST_CASE("a script with a caption wider than the key-hint row is refused before the session starts, exit 1",
          "[session][captions][headless]")
{
    const test::TempFolder folder;
    copy_example("n-to-l", folder);
    {
        std::ofstream script(folder / "wide.keys");
        script << "ENTER ENTER\n;; " << std::string(80, 'w') << "\nENTER\n";
    }
    const auto result = test::run_apcs({"--keys", (folder / "wide.keys").string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 1);
    REQUIRE(result.out.empty());
    REQUIRE(result.err == (folder / "wide.keys").string() +
                              ":2: expected a caption of at most 79 columns (the key-hint row of the 80x24 screen); "
                              "found 80\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "ani1.dat"));
}

TEST_CASE("every key of a shipped lesson after its opening answers is a caption's, so that each screen the class "
          "sees has its caption beside it",
          "[session][captions][teaching]")
{
    // SPEC 3.2: a caption shows beside the screen its keys made; a key before the first caption
    // would play with the caption row empty, and the last caption is about the last screen.
    const std::vector<std::string> lessons = shipped_lessons();
    REQUIRE(lessons.size() >= 3);
    for (const std::string& lesson : lessons) {
        CAPTURE(lesson);
        const KeyScript script = read_lesson(lesson);
        REQUIRE_FALSE(script.captions.empty());
        REQUIRE(script.captions.front().before_event == script.preamble_end);
        for (const ScriptCaption& caption : script.captions)
            REQUIRE_FALSE(caption.text.empty());
    }
}

TEST_CASE("every shipped lesson replays headless, each caption over its approved screen, ascii and braille",
          "[session][captions][teaching][headless]")
{
    for (const std::string& lesson : shipped_lessons())
        for (const auto& [glyphs, name] : {std::pair{GlyphSet::ascii, "ascii"}, std::pair{GlyphSet::braille, "braille"}}) {
            CAPTURE(lesson, name);
            const std::string stem = std::filesystem::path(lesson).replace_extension().string();
            test::check_golden("lessons/" + stem + "-captions-" + name + ".txt", caption_screens(lesson, glyphs));
        }
}

TEST_CASE("apcs fit regenerates every shipped session's in-betweens byte for byte from the files it wrote",
          "[session][headless][slopes]")
{
    // SPEC §2.1: the session writes each adjusted path file with its SLOPES, so batch fitting of the
    // same files gives the same frames (N-to-L's way4 was adjusted with slopes 0.5 1, the snake's
    // way7 with 1 0.5, the stick's way1 with 0 0).
    const std::tuple<const char*, const char*, const char*> examples[] = {
        {"n-to-l", "way1.dat", "way4.dat"}, {"stick", "way1.dat", "way5.dat"}, {"snake-apple", "way1.dat", "way7.dat"}};
    for (const auto& [example, first, last] : examples) {
        CAPTURE(example);
        const test::TempFolder folder;
        copy_example(example, folder);
        const auto session = test::run_apcs({"--keys", (folder / "session.keys").string(), "--workdir",
                                             folder.path().string()});
        REQUIRE(session.status == 0);
        const std::filesystem::path batch = folder / "batch";
        std::filesystem::create_directory(batch);
        const auto fitted = test::run_apcs({"fit", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                            (folder / first).string(), (folder / last).string(), "--out",
                                            batch.string()});
        REQUIRE(fitted.status == 0);
        for (int k = 1; k <= 12; ++k) {
            const std::string name = inbetween_file_name(static_cast<std::size_t>(k));
            CAPTURE(name);
            // read_all gives "" for a file that is not there: both runs must have written it.
            REQUIRE(std::filesystem::exists(folder / name));
            REQUIRE(std::filesystem::exists(batch / name));
            REQUIRE(test::read_all(batch / name) == test::read_all(folder / name));
        }
    }
}

TEST_CASE("the snake scene plays the snake session's frames: its path files are the session's, SLOPES and all",
          "[session][headless][scene]")
{
    // Issue 29: the scene applied one STAFF to 3-column copies and was up to 0.69 off the session.
    const test::TempFolder folder;
    copy_example("snake-apple", folder);
    REQUIRE(test::run_apcs({"--keys", (folder / "session.keys").string(), "--workdir", folder.path().string()})
                .status == 0);
    // The scene's paths are what the session wrote (their comment lines aside).
    for (const auto& [shipped, written] : {std::pair{"session-ani1.dat", "ani1.dat"}, {"session-way7.dat", "way7.dat"}}) {
        CAPTURE(shipped);
        const Expected<DatFile> mine = read_dat_file(folder / shipped);
        const Expected<DatFile> session = read_dat_file(folder / written);
        REQUIRE((mine && session));
        REQUIRE(mine->slopes.has_value());
        REQUIRE(mine->slopes->start == session->slopes->start);
        REQUIRE(mine->slopes->end == session->slopes->end);
        REQUIRE(mine->parts.size() == session->parts.size());
        for (std::size_t p = 0; p < mine->parts.size(); ++p) {
            REQUIRE(mine->parts[p].points.size() == session->parts[p].points.size());
            for (std::size_t i = 0; i < mine->parts[p].points.size(); ++i) {
                REQUIRE(mine->parts[p].points[i].position == session->parts[p].points[i].position);
                REQUIRE(mine->parts[p].points[i].staff == session->parts[p].points[i].staff);
            }
        }
    }
    // As it is, without --spacing: the scene's spacing is nearest, the session's (issue 44).
    const auto played = test::run_apcs({"play", (folder / "snake-apple.scn").string(), "--print"});
    REQUIRE(played.status == 0);
    // "# frame k", "# object snake", its points, "# object apple", ...
    std::istringstream print(played.out);
    std::vector<std::vector<Vec3>> snake;
    bool in_snake = false;
    for (std::string line; std::getline(print, line);) {
        if (line.starts_with("# frame"))
            snake.emplace_back();
        else if (line.starts_with("# object"))
            in_snake = line == "# object snake";
        else if (in_snake) {
            std::istringstream numbers(line);
            Vec3 point;
            numbers >> point.x >> point.y >> point.z;
            snake.back().push_back(point);
        }
    }
    REQUIRE(snake.size() == 14);
    double worst = 0.0;
    for (std::size_t k = 1; k <= 12; ++k) {
        const Expected<Graphic> inbetween = read_key_frame(folder / inbetween_file_name(k));
        REQUIRE(inbetween);
        const std::vector<Vec3> points = inbetween->all_points();
        REQUIRE(points.size() == snake[k].size());
        for (std::size_t i = 0; i < points.size(); ++i)
            worst = std::max(worst, distance(points[i], snake[k][i]));
    }
    // The inb files hold six decimals: the scene's frames are them to their rounding.
    REQUIRE(worst <= 1e-6);
}

TEST_CASE("a headless replay draws a screen a step, not a key: 10 and 2,000 staff keys draw as many",
          "[session][headless]")
{
    const auto screens_drawn = [](int staff_keys) {
        const test::TempFolder folder;
        copy_example("n-to-l", folder);
        FolderFiles files(folder.path());
        Session session({}, files);
        std::string text = "ENTER ENTER\nTEXT 0 90 100\nENTER\nTEXT way1.dat\nENTER ENTER\n8\n";
        for (int key = 0; key < staff_keys; ++key)
            text += key % 2 == 0 ? "6\n" : "4\n";
        const Expected<KeyScript> script = parse_captioned_key_script(text, "staff.keys");
        REQUIRE(script);
        ReplayDriver replay(session, *script, "staff.keys", ReplayPace{}, {}, ReplayAudience::headless);
        std::ostringstream transcript;
        const std::size_t drawn = run_headless_session(replay, session, GlyphSet::ascii, transcript);
        // Each step's screen is printed, the staff's last.
        const std::string printed = transcript.str();
        REQUIRE(printed.find("--- step 3: global or local control") != std::string::npos);
        REQUIRE(printed.find("--- step 4: four-line staff") != std::string::npos);
        return drawn;
    };
    const std::size_t few = screens_drawn(10);
    CAPTURE(few);
    REQUIRE(few < 30);
    REQUIRE(screens_drawn(2'000) == few);
}
