#include "apcs/formats/key_script.h"
#include "apcs/formats/path_files.h"
#include "apcs/session/session.h"
#include "apcs/screens/words.h"
#include "apcs/screens/text_console.h"

#include "apcs/session/session_files.h"

#include "support/png_pixels.h"
#include "support/xml_elements.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace apcs;
using apcs::test::type;

namespace {

void press(Session& session, std::initializer_list<KeyEvent> keys)
{
    for (const KeyEvent& key : keys)
        session.handle(key);
}

KeyEvent ch(char c) { return KeyEvent::typed(static_cast<char32_t>(c)); }
const KeyEvent enter = KeyEvent::of(Key::enter);
const KeyEvent escape = KeyEvent::of(Key::escape);

// The text screen, each row without its trailing blanks.
std::string screen_text(const Session& session)
{
    const CellGrid grid = session.screen().text;
    std::string shown;
    for (int row = 0; row < grid.rows(); ++row) {
        std::string line = grid.row_text(row);
        shown += line.erase(line.find_last_not_of(' ') + 1) + "\n";
    }
    return shown;
}

std::string graphics_message(const Session& session)
{
    for (const TextLine& line : session.screen().picture.text)
        if (line.row == 18)
            return line.text;
    return {};
}

MemoryFiles example_files()
{
    MemoryFiles files;
    files.files["key1.dat"] = "0 0 0\n0 0 10\n0 6 0\n0 6 10\n";
    files.files["key2.dat"] = "0 0 10\n0 0 0\n0 5 0\n";
    files.files["way1.dat"] = "0 0 0\n3 -4 5\n1 1 7\n0 0 10\n";
    return files;
}

// Through step 1 with the thesis' default answers: KEY1, KEY2 and the split.
void reach_view_prompt(Session& session)
{
    type(session, "");
    type(session, "");
    REQUIRE(session.leaf_name() == "ask_view");
}

// Through steps 1–3 with the thesis' default answers and way1.dat as the first path.
void reach_control_choice(Session& session)
{
    reach_view_prompt(session);
    type(session, "");
    type(session, "way1.dat");
    type(session, "");
}

} // namespace

TEST_CASE("step 1 and 2 print the thesis' words with the real file names", "[session]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    REQUIRE(screen_text(session).starts_with("Please keyin the KEY1 filename!\n_"));
    type(session, "");
    type(session, "KEY2.DAT"); // a missing name: asked again
    REQUIRE(session.leaf_name() == "ask_key2");
    REQUIRE(screen_text(session).find("KEY2.DAT: cannot open: No such file or directory\n"
                                      "Please keyin the KEY2 filename!") != std::string::npos);
    type(session, "key2.dat");
    REQUIRE(session.leaf_name() == "ask_view");
    const std::string expected = "Please keyin the KEY1 filename!\n"
                                 "key1.dat\n"
                                 "Please keyin the KEY2 filename!\n"
                                 "KEY2.DAT\n"
                                 "KEY2.DAT: cannot open: No such file or directory\n"
                                 "Please keyin the KEY2 filename!\n"
                                 "key2.dat\n"
                                 "Adding_Points work is done.\n"
                                 "You must Input 2 Files to adjust animation path:\n"
                                 "ani1.dat and ani4.dat.\n"
                                 "ani1.dat contained the first graphic point to adjust its path.\n"
                                 "ani4.dat contained the last graphic point to adjust its path.\n"
                                 "Please input the VIEWER'S direction and delay time:\n"
                                 "THETA ,PHI & delay-time value.\n";
    REQUIRE(screen_text(session).starts_with(expected));
    // The split wrote one path file per graphic point: KEY2 gained (0,0,5) by Algorithm 2.
    REQUIRE(files.files["ani2.dat"] == "0 0 10\n0 0 5\n");
    REQUIRE(files.files["ani4.dat"] == "0 6 10\n0 5 0\n");
}

TEST_CASE("a wrong answer at each prompt says why and asks again", "[session]")
{
    MemoryFiles files = example_files();
    files.files["bad.dat"] = "0 0 0\nx 1 1\n";
    files.files["off.dat"] = "0 1 0\n0 0 10\n";
    Session session({}, files);
    type(session, "nothing.dat");
    REQUIRE(session.leaf_name() == "ask_key1");
    type(session, "bad.dat");
    REQUIRE(session.leaf_name() == "ask_key1");
    REQUIRE(screen_text(session).find("bad.dat:2: expected a number, found 'x'") != std::string::npos);
    type(session, "");
    type(session, "");
    type(session, "30 forty 200");
    REQUIRE(session.leaf_name() == "ask_view");
    type(session, "30 40");
    REQUIRE(session.leaf_name() == "ask_view");
    type(session, "30 40 -5");
    REQUIRE(session.leaf_name() == "ask_view");
    type(session, "30, 40, 200");
    REQUIRE(session.leaf_name() == "ask_path_file");
    type(session, "../way1.dat");
    REQUIRE(session.leaf_name() == "ask_path_file");
    REQUIRE(screen_text(session).find("../way1.dat: expected a file in the session's folder") != std::string::npos);
    type(session, "/tmp/way1.dat");
    REQUIRE(session.leaf_name() == "ask_path_file");
    type(session, "off.dat");
    REQUIRE(session.leaf_name() == "ask_path_file");
    REQUIRE(screen_text(session).find("off.dat:1: the path starts at (0, 1, 0); expected the first graphic point's "
                                      "KEY1\n position (0, 0, 0)") != std::string::npos);
    type(session, "ani4.dat"); // the last point's path offered for the first point
    REQUIRE(session.leaf_name() == "ask_path_file");
    type(session, "");
    REQUIRE(session.leaf_name() == "ask_slopes");
    type(session, "1.5 1");
    REQUIRE(session.leaf_name() == "ask_slopes");
    type(session, "0.5"); // one slope per line, as in fig. 4.2.3
    REQUIRE(session.leaf_name() == "ask_slopes");
    type(session, "0");
    REQUIRE(session.leaf_name() == "control_choice");
    REQUIRE(session.screen().graphics);
}

TEST_CASE("global control applies every staff key to all control points", "[session][staff]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_control_choice(session);
    REQUIRE(session.leaf_name() == "control_choice");
    press(session, {ch('8')});
    REQUIRE(session.leaf_name() == "staff");
    // TENSION: 6 6 6 (+0.15), 4 (−0.05), L (+0.15), J (−0.15), right arrow (+0.05) = +0.15.
    press(session, {ch('6'), ch('6'), ch('6'), ch('4'), ch('L'), ch('J'), KeyEvent::of(Key::right), enter});
    // CONTINUITY: 4 4, then Esc puts it back to 0.
    press(session, {ch('4'), ch('4'), escape});
    // BIAS: left arrow −0.05; ACCELERATION: L L +0.30.
    press(session, {KeyEvent::of(Key::left), enter, ch('L'), ch('L'), enter});
    REQUIRE(session.leaf_name() == "ask_again");
    press(session, {ch('N')});
    REQUIRE(session.leaf_name() == "ask_next_path");
    REQUIRE(files.files["way1.dat"] == "SLOPES 1 1\n0 0 0 0.15 0 -0.05 0.3\n3 -4 5 0.15 0 -0.05 0.3\n1 1 7 0.15 0 -0.05 0.3\n"
                                       "0 0 10 0.15 0 -0.05 0.3\n");
}

TEST_CASE("staff values clamp at -1 and +1", "[session][staff]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_control_choice(session);
    press(session, {ch('8')});
    for (int i = 0; i < 20; ++i)
        press(session, {ch('L')});
    press(session, {enter});
    for (int i = 0; i < 30; ++i)
        press(session, {ch('J')});
    press(session, {enter, enter, enter, ch('n')});
    REQUIRE(files.files["way1.dat"].starts_with("SLOPES 1 1\n0 0 0 1 -1 0 0\n"));
}

TEST_CASE("local control changes the picked middle region only", "[session][staff]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_control_choice(session);
    press(session, {ch('2')});
    REQUIRE(session.leaf_name() == "region_first");
    // The arrow starts at the top-left; the first 6 moves it to control point 1, the next to 2.
    press(session, {ch('6'), ch('6'), enter});
    REQUIRE(session.leaf_name() == "region_last");
    press(session, {ch('4'), enter}); // point 1 is before the first: refused
    REQUIRE(session.leaf_name() == "region_last");
    REQUIRE(graphics_message(session) == "The last control point must come after the first (point 2)");
    press(session, {KeyEvent::of(Key::right), KeyEvent::of(Key::right), enter});
    REQUIRE(session.leaf_name() == "staff");
    press(session, {ch('6'), ch('6'), enter, enter, enter, ch('6'), enter, ch('N')});
    // Points 2 and 3 (indices 1, 2) get t = 0.1; a = 0.05 starts at point 2 and ends at point 3.
    REQUIRE(files.files["way1.dat"] == "SLOPES 1 1\n0 0 0 0 0 0 0\n3 -4 5 0.1 0 0 0.05\n1 1 7 0.1 0 0 0\n0 0 10 0 0 0 0\n");
}

TEST_CASE("Y adjusts the path again from the control choice", "[session]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('y')});
    REQUIRE(session.leaf_name() == "control_choice");
}

TEST_CASE("a whole session writes the paths, the in-betweens and the log", "[session]")
{
    MemoryFiles files = example_files();
    files.files["way4.dat"] = "0 6 10\n-3 10 5\n0 5 0\n";
    SessionSettings settings;
    settings.inbetween_count = 5;
    Session session(settings, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('N')});
    press(session, {ch('x')}); // only Y goes on
    REQUIRE(session.leaf_name() == "ask_next_path");
    press(session, {ch('Y')});
    type(session, "way4.dat");
    type(session, "1 1");
    press(session, {ch('8'), enter, enter, enter, enter, ch('N')});
    REQUIRE(session.leaf_name() == "ask_stop");
    press(session, {ch('x')});
    REQUIRE(session.leaf_name() == "ask_stop");
    press(session, {enter});
    REQUIRE(session.leaf_name() == "ask_draw");
    REQUIRE(screen_text(session).find("Press <ENTER> to Stop the work !\n"
                                      "Please wait a moment! Surface Fitting is working now .....\n"
                                      "Surface-Fitting work is done.\n"
                                      "Press any key to draw the animation effect!\n") != std::string::npos);
    REQUIRE(files.files.count("inb005.dat") == 1);
    REQUIRE(files.files.count("inb006.dat") == 0);
    press(session, {KeyEvent::of(Key::space)});
    REQUIRE(session.animating());
    REQUIRE(session.delay_ms() == 200);
    press(session, {KeyEvent::of(Key::space)}); // pause
    REQUIRE_FALSE(session.animating());
    press(session, {KeyEvent::of(Key::space)});
    for (int i = 0; i < 10; ++i)
        session.tick();
    REQUIRE(session.leaf_name() == "stopped");
    press(session, {enter});
    REQUIRE(session.leaf_name() == "overlaid");
    press(session, {enter});
    REQUIRE(session.finished());
    REQUIRE(screen_text(session).find("APCS is done. Files written:\n  ani1.dat\n") != std::string::npos);
    REQUIRE(files.log_lines.back() == "end of session");
    REQUIRE(session.written_files().size() == 4 + 2 + 5);
}

TEST_CASE("in-betweens left by an earlier, longer run are pointed out on screen and in the log, not deleted",
          "[session]")
{
    MemoryFiles files = example_files();
    files.files["way4.dat"] = "0 6 10\n-3 10 5\n0 5 0\n";
    for (const char* earlier : {"inb004.dat", "inb006.dat", "inb007.dat", "inb009.dat"})
        files.files[earlier] = "; from an earlier run\n0 0\n1 1\n";
    SessionSettings settings;
    settings.inbetween_count = 5;
    Session session(settings, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), ch('Y')});
    type(session, "way4.dat");
    type(session, "1 1");
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), enter});
    REQUIRE(session.leaf_name() == "ask_draw");
    const std::string note = "inb006.dat to inb009.dat (3 files) are from an earlier run (not rewritten)";
    REQUIRE(screen_text(session).find(note + "\n") != std::string::npos);
    REQUIRE(std::find(files.log_lines.begin(), files.log_lines.end(), note) != files.log_lines.end());
    REQUIRE(files.files["inb009.dat"] == "; from an earlier run\n0 0\n1 1\n");
}

TEST_CASE("a number too small for a double is 0 at a prompt, as in a .dat file", "[session]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_view_prompt(session);
    type(session, "1e-400 -1e-310 200");
    REQUIRE(session.leaf_name() == "ask_path_file");
}

TEST_CASE("a typed answer keeps 200 bytes at most: a character that would pass them is refused, a shorter one after "
          "it fits",
          "[session][cells]")
{
    MemoryFiles files = example_files();
    Session session(SessionSettings{}, files);
    for (int typed = 0; typed < 199; ++typed)
        session.handle(KeyEvent::typed(U'a'));
    session.handle(KeyEvent::typed(U'\u6F22')); // 3 bytes: 202
    session.handle(KeyEvent::typed(U'b'));       // 1 byte: 200
    session.handle(KeyEvent::typed(U'c'));       // 201
    std::string shown;
    const CellGrid grid = session.screen().text;
    for (int row = 0; row < grid.rows(); ++row)
        shown += grid.row_text(row);
    CHECK(shown.find("\u6F22") == std::string::npos);
    CHECK(shown.find("ab_") != std::string::npos);
    CHECK(shown.find('c') == std::string::npos);
}

TEST_CASE("a typed answer holds 66 Chinese characters, as the manual says (3 bytes each: 198 of 200)",
          "[session][cells]")
{
    MemoryFiles files = example_files();
    Session session(SessionSettings{}, files);
    for (int typed = 0; typed < 70; ++typed)
        session.handle(KeyEvent::typed(U'\u5B57'));
    session.handle(enter);
    // The answer is refused (no such file) and the refusal names it whole.
    std::string shown;
    const CellGrid grid = session.screen().text;
    for (int row = 0; row < grid.rows(); ++row)
        shown += grid.row_text(row);
    std::string sixty_six;
    for (int typed = 0; typed < 66; ++typed)
        sixty_six += "\u5B57";
    CHECK(shown.find(sixty_six) != std::string::npos);
    CHECK(shown.find(sixty_six + "\u5B57") == std::string::npos);
}

TEST_CASE("wide characters typed at a prompt take two columns, zero-width ones are refused, and a wide name reads",
          "[session][cells]")
{
    MemoryFiles files = example_files();
    files.files["\u6F22\u5B57.dat"] = files.files["key1.dat"];
    Session session(SessionSettings{}, files);
    for (const char32_t typed : std::u32string(U"\u6F22\u0301\u200B\u5B57.dat"))
        session.handle(KeyEvent::typed(typed));
    const CellGrid grid = session.screen().text;
    int row = grid.rows() - 1;
    while (row > 0 && grid.at(0, row) == U' ')
        --row;
    REQUIRE(grid.row_text(row).starts_with("\u6F22\u5B57.dat_ "));
    REQUIRE(grid.at(4, row) == U'.');
    REQUIRE(grid.at(8, row) == U'_');
    session.handle(enter);
    REQUIRE(session.leaf_name() == "ask_key2");

    // 41 wide characters are 82 columns: the 41st wraps to the next row whole.
    std::string long_line;
    for (int i = 0; i < 41; ++i)
        long_line += "\u6F22";
    TextConsole console;
    console.print_line(long_line);
    const CellGrid wrapped = console.render(false);
    REQUIRE(wrapped.at(78, 0) == U'\u6F22');
    REQUIRE(wrapped.at(79, 0) == CellGrid::wide_tail);
    REQUIRE(wrapped.row_text(1).starts_with("\u6F22 "));
}

TEST_CASE("a closed graphic's second path starts from the first path's values", "[session]")
{
    MemoryFiles files;
    files.files["key1.dat"] = "PART ring CLOSED\n0 0 0\n0 2 0\n0 2 2\n0 0 0\n";
    files.files["key2.dat"] = "PART ring CLOSED\n4 0 0\n4 3 0\n4 3 3\n4 0 0\n";
    Session session({}, files);
    type(session, "");
    type(session, "");
    type(session, "");
    type(session, "");
    type(session, "");
    press(session, {ch('8'), ch('6'), ch('6'), enter, enter, enter, enter, ch('N'), ch('Y')});
    type(session, ""); // ani4.dat, which holds the same point as ani1.dat
    type(session, "");
    press(session, {ch('8')});
    REQUIRE(session.screen().picture.text.size() > 1);
    bool shows_tension = false;
    for (const TextLine& line : session.screen().picture.text)
        shows_tension = shows_tension || (line.row == 19 && line.text == "+0.10");
    REQUIRE(shows_tension);
}

TEST_CASE("key scripts parse and format back to the same keys", "[session][keys]")
{
    const Expected<std::vector<KeyEvent>> script =
        parse_key_script("; comment\nENTER\nTEXT 30 40 200\nENTER\n6 6 J L ESC ; steps\n"
                         "LEFT RIGHT UP DOWN SPACE BACKSPACE\nTEXT ;\n",
                         "s.keys");
    REQUIRE(script.has_value());
    REQUIRE(script->size() == 1 + 9 + 1 + 5 + 6 + 1);
    REQUIRE((*script)[3] == KeyEvent::of(Key::space));
    REQUIRE(script->back() == KeyEvent::typed(U';'));
    REQUIRE(*parse_key_script(format_key_script(*script), "again.keys") == *script);
    const Expected<std::vector<KeyEvent>> bad = parse_key_script("ENTER\nPAGEUP\n", "bad.keys");
    REQUIRE_FALSE(bad.has_value());
    REQUIRE(bad.error().to_string().starts_with("bad.keys:2: expected a single printable character"));
}

TEST_CASE("a key file is never written, even when it shares a name the session writes", "[session]")
{
    MemoryFiles files = example_files();
    files.files["ANI1.DAT"] = files.files["key1.dat"];
    Session session({}, files);
    type(session, "ANI1.DAT");
    type(session, "");
    // The split would write ani1.dat: refused, KEY2 asked again, the key untouched.
    REQUIRE(session.leaf_name() == "ask_key2");
    REQUIRE(screen_text(session).find("ani1.dat: is a key file; key files are never written") != std::string::npos);
    REQUIRE(files.files.count("ani1.dat") == 0);
    REQUIRE(files.files["ANI1.DAT"] == files.files["key1.dat"]);
}

TEST_CASE("the animation stops on Esc and replays from the start on R", "[session]")
{
    MemoryFiles files = example_files();
    files.files["way4.dat"] = "0 6 10\n0 5 0\n";
    Session session({}, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), ch('Y')});
    type(session, "way4.dat");
    type(session, "");
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), enter, enter});
    REQUIRE(session.animating());
    session.tick();
    session.tick();
    REQUIRE(graphics_message(session) == "In-between 2 of 12: inb002.dat");
    press(session, {ch('R')});
    REQUIRE(graphics_message(session) == "KEY1: key1.dat");
    press(session, {escape});
    REQUIRE(session.leaf_name() == "stopped");
    REQUIRE_FALSE(session.animating());
}

TEST_CASE("? and F1 open the help screen of the step, any key closes it", "[session][help]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    press(session, {KeyEvent::of(Key::f1)});
    REQUIRE(screen_text(session).starts_with("APCS help - the keys of step 1: KEY1 file\n"));
    REQUIRE(screen_text(session).find("Backspace") != std::string::npos);
    press(session, {ch('x')}); // closes, is not typed
    REQUIRE(screen_text(session).starts_with("Please keyin the KEY1 filename!\n_"));
    type(session, "?"); // the answer ? alone is the help too
    REQUIRE(screen_text(session).starts_with("APCS help"));
    press(session, {enter});
    REQUIRE(session.leaf_name() == "ask_key1");
    reach_control_choice(session);
    press(session, {ch('8'), ch('?')});
    REQUIRE_FALSE(session.screen().graphics);
    REQUIRE(screen_text(session).find("  J, L            three steps left, right (Shift-J, Shift-L)") != std::string::npos);
    press(session, {ch('6')}); // closes the help; the staff is unchanged
    REQUIRE(session.leaf_name() == "staff");
    REQUIRE(graphics_message(session) == "way1.dat: TENSION  control points 1 to 4 of 4");
}

TEST_CASE("q asks before quitting an unsaved path, Enter means N, Y ends with the files listed", "[session][quit]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_control_choice(session);
    press(session, {ch('8'), ch('6'), ch('q')});
    REQUIRE(graphics_message(session) == "Quit without saving this path ? (Y/N)");
    press(session, {ch('6')}); // not an answer
    REQUIRE(graphics_message(session) == "Quit without saving this path ? (Y/N)");
    press(session, {enter});
    REQUIRE(session.leaf_name() == "staff");
    press(session, {ch('Q'), ch('y')});
    REQUIRE(session.finished());
    REQUIRE(screen_text(session).find("APCS is done. Files written:\n  ani1.dat\n") != std::string::npos);
    REQUIRE(files.files["way1.dat"] == "0 0 0\n3 -4 5\n1 1 7\n0 0 10\n"); // not saved
    REQUIRE(files.log_lines[files.log_lines.size() - 2] == "quit at step 4: four-line staff");
}

TEST_CASE("Esc on an empty prompt asks Quit APCS ? (Y/N) — N, Esc and Enter go back to the prompt as it was",
          "[session][quit]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    const std::string prompt = screen_text(session);
    press(session, {escape});
    REQUIRE(screen_text(session).starts_with("Please keyin the KEY1 filename!\nQuit APCS ? (Y/N)_\n"));
    press(session, {ch('x'), ch('q')}); // no answer: the question stays, nothing is typed
    REQUIRE(screen_text(session).starts_with("Please keyin the KEY1 filename!\nQuit APCS ? (Y/N)_\n"));
    press(session, {ch('N')});
    REQUIRE(screen_text(session) == prompt);
    for (const KeyEvent& back : {ch('n'), escape, enter}) {
        press(session, {escape});
        REQUIRE(screen_text(session) != prompt);
        press(session, {back});
        REQUIRE(screen_text(session) == prompt);
        REQUIRE(session.leaf_name() == "ask_key1");
    }
    // The line is kept through the question: Esc on typed text clears it (as DOS did), never asks.
    press(session, {ch('a'), ch('b'), escape});
    REQUIRE(screen_text(session) == prompt);
    type(session, "key1.dat");
    REQUIRE(session.leaf_name() == "ask_key2");
}

TEST_CASE("Y to Quit APCS ? at a prompt ends the session as q does, with the files written listed", "[session][quit]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    reach_view_prompt(session);
    press(session, {escape, ch('y')});
    REQUIRE(session.finished());
    REQUIRE(screen_text(session).find("APCS is done. Files written:\n  ani1.dat\n  ani2.dat\n") != std::string::npos);
    REQUIRE(files.log_lines[files.log_lines.size() - 2] == "quit at step 2: view and delay");
}

TEST_CASE("the help at a text prompt names the answer an empty line takes at that prompt", "[session][help]")
{
    MemoryFiles files = example_files();
    SessionSettings settings;
    settings.slopes = EndSlopes{0.5, 0.25};
    Session session(settings, files);
    const auto help_names = [&](const std::string& answer) {
        const std::string before = screen_text(session);
        press(session, {KeyEvent::of(Key::f1)});
        const bool named = screen_text(session).find("  Enter           answer; an empty line takes " + answer + "\n") !=
                           std::string::npos;
        press(session, {ch('x')});
        // The thesis' prompt rows come back byte for byte.
        return named && screen_text(session) == before;
    };
    REQUIRE(help_names("key1.dat"));
    type(session, "");
    REQUIRE(help_names("key2.dat"));
    type(session, "");
    REQUIRE(help_names("30 40 200"));
    type(session, "");
    REQUIRE(help_names("ani1.dat"));
    type(session, "way1.dat");
    REQUIRE(help_names("0.5 0.25"));
    type(session, "0.5"); // DS[0] alone: Enter now takes DD[N] only
    REQUIRE(help_names("0.25"));
    type(session, "?"); // the answer ? alone names it too
    REQUIRE(screen_text(session).find("an empty line takes 0.25\n") != std::string::npos);
}

TEST_CASE("P writes the graphics screen as the first free apcsNNN.png and says so", "[session][picture]")
{
    MemoryFiles files = example_files();
    files.files["apcs001.png"] = "someone's picture";
    Session session({}, files);
    reach_control_choice(session);
    press(session, {ch('P')});
    REQUIRE(graphics_message(session) == "wrote apcs002.png");
    REQUIRE(files.files["apcs001.png"] == "someone's picture");
    REQUIRE(files.files["apcs002.png"].starts_with("\x89PNG"));
    press(session, {ch('8')}); // the next key takes the notice away
    REQUIRE(graphics_message(session) == "way1.dat: TENSION  control points 1 to 4 of 4");
}

TEST_CASE("a path of two control points says that t, c and b act at interior points", "[session][staff]")
{
    MemoryFiles files = example_files();
    Session session({}, files);
    type(session, "");
    type(session, "");
    type(session, "");
    type(session, ""); // ani1.dat, as split wrote it: two control points
    type(session, "");
    press(session, {ch('8')});
    REQUIRE(graphics_message(session) == "TENSION acts at interior control points: add one with W at the 8/2 choice");
    press(session, {enter, enter, enter});
    REQUIRE(graphics_message(session).starts_with("ani1.dat: ACCELERATION  control points 1 to 2 of 2"));
}

TEST_CASE("the command line's values are the answers Enter takes, and seed 3-column path files", "[session]")
{
    MemoryFiles files = example_files();
    SessionSettings settings;
    settings.theta_degrees = 0;
    settings.phi_degrees = 90;
    settings.delay_ms = 50;
    settings.slopes = EndSlopes{0.5, 0.25};
    settings.staff = {0.1, 0, 0, 0};
    Session session(settings, files);
    type(session, "");
    type(session, "");
    type(session, "");
    REQUIRE(screen_text(session).find("THETA ,PHI & delay-time value.\n0 90 50\n") != std::string::npos);
    type(session, "way1.dat");
    type(session, "");
    REQUIRE(files.log_lines.back() == "slopes DS[0] 0.5, DD[N] 0.25");
    press(session, {ch('8'), enter, enter, enter, enter, ch('n')});
    REQUIRE(files.files["way1.dat"].starts_with("SLOPES 0.5 0.25\n0 0 0 0.1 0 0 0\n"));
}

TEST_CASE("the session's --png writes the overlay of all frames when the animation ends", "[session][picture]")
{
    MemoryFiles files = example_files();
    files.files["way4.dat"] = "0 6 10\n0 5 0\n";
    SessionSettings settings;
    settings.overlay_png = "all.png";
    Session session(settings, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), ch('Y')});
    type(session, "way4.dat");
    type(session, "");
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), enter, enter});
    while (session.animating())
        session.tick();
    REQUIRE(files.files.count("all.png") == 0);
    press(session, {enter});
    REQUIRE(session.leaf_name() == "overlaid");
    REQUIRE(test::grey_picture(files.files["all.png"]).height == 522);
    REQUIRE(graphics_message(session) == "wrote all.png");
}

TEST_CASE("the session's --png-raw writes the bare 720x348 overlay beside --png's 720x522", "[session][picture]")
{
    MemoryFiles files = example_files();
    files.files["way4.dat"] = "0 6 10\n0 5 0\n";
    SessionSettings settings;
    settings.overlay_png = "all.png";
    settings.overlay_png_raw = "raw.png";
    Session session(settings, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), ch('Y')});
    type(session, "way4.dat");
    type(session, "");
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), enter, enter});
    while (session.animating())
        session.tick();
    press(session, {enter});
    const test::GreyPicture seen = test::grey_picture(files.files["all.png"]);
    const test::GreyPicture bare = test::grey_picture(files.files["raw.png"]);
    REQUIRE(seen.height == 522);
    REQUIRE(bare.height == 348);
    // The same raster: picture row 3 shows raster row 2.
    for (png_uint_32 x = 0; x < 720; ++x)
        REQUIRE(seen.lit(x, 3) == bare.lit(x, 2));
}

TEST_CASE("the session's --svg writes the overlay of all frames as vector lines", "[session][picture][svg]")
{
    MemoryFiles files = example_files();
    files.files["way4.dat"] = "0 6 10\n0 5 0\n";
    SessionSettings settings;
    settings.overlay_svg = "all.svg";
    Session session(settings, files);
    reach_control_choice(session);
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), ch('Y')});
    type(session, "way4.dat");
    type(session, "");
    press(session, {ch('8'), enter, enter, enter, enter, ch('N'), enter, enter});
    while (session.animating())
        session.tick();
    REQUIRE(files.files.count("all.svg") == 0);
    press(session, {enter});
    const auto elements = test::XmlReader::read(files.files["all.svg"]);
    REQUIRE(elements);
    // The boundary's four lines, then one stroke a frame: KEY1, 12 in-betweens, KEY2.
    const auto paths = test::elements_named(*elements, "path");
    CHECK(std::count_if(paths.begin(), paths.end(), [](const test::XmlElement& element) {
              return element.attributes.at("class") != "mark";
          }) == 4 + 14);
    REQUIRE(graphics_message(session) == "wrote all.svg");
}

TEST_CASE("--delay given with --keys replaces the delay the view prompt's answer gives, and apcs.log says so",
          "[session]")
{
    MemoryFiles files = example_files();
    SessionSettings settings;
    settings.delay_ms = 1000;
    SECTION("overriding")
    {
        settings.delay_overrides_answer = true;
        Session session(settings, files);
        reach_view_prompt(session);
        type(session, "0 90 100");
        REQUIRE(session.delay_ms() == 1000);
        REQUIRE(files.log_lines.back() == "view: theta 0, phi 90, delay 1000 ms (--delay; the answer gave 100)");
    }
    SECTION("only the default of an empty answer")
    {
        Session session(settings, files);
        reach_view_prompt(session);
        type(session, "0 90 100");
        REQUIRE(session.delay_ms() == 100);
        REQUIRE(files.log_lines.back() == "view: theta 0, phi 90, delay 100 ms");
    }
}
