// Captions of a guided replay: ";;" comments of a key script, laid over the screen.
#include "apcs/formats/key_script.h"
#include "apcs/screens/replay_caption.h"
#include "apcs/session/session_files.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

using namespace apcs;

TEST_CASE("a ' — —' comment is a caption placed after the keys before it — ' —' comments and TEXT are not",
          "[session][captions]")
{
    const Expected<KeyScript> script = parse_captioned_key_script(";; Step 1: the key frames\n"
                                                                  "ENTER ; KEY1\n"
                                                                  "ENTER   ;;  Step 2: the split  \n"
                                                                  "TEXT ;; typed, not a caption\n"
                                                                  "; a plain comment\n"
                                                                  "8 6 ;;\n",
                                                                  "class.keys");
    REQUIRE(script);
    REQUIRE(script->events.size() == 2 + 23 + 2);
    REQUIRE(script->captions == std::vector<ScriptCaption>{{0, "Step 1: the key frames"},
                                                           {2, "Step 2: the split"},
                                                           {27, ""}});
    REQUIRE(caption_at(*script, 0)->text == "Step 1: the key frames");
    REQUIRE(caption_at(*script, 1)->text == "Step 1: the key frames");
    REQUIRE(caption_at(*script, 2)->text == "Step 2: the split");
    REQUIRE(caption_at(*script, 27)->text.empty());
    // The keys are those of the script read without captions.
    REQUIRE(*parse_key_script(";; x\nENTER ;; y\n", "a.keys") == parse_captioned_key_script(";; x\nENTER ;; y\n", "a.keys")->events);
    REQUIRE(caption_at(KeyScript{}, 5) == nullptr);
}

namespace {

// The session at the waypoint editor of way-less key frames: its message line says which control
// point the arrow is on.
void open_waypoint_editor(Session& session, MemoryFiles& files)
{
    files.files["key1.dat"] = "0 0 0\n0 6 0\n";
    files.files["key2.dat"] = "0 0 10\n0 6 10\n";
    for (const char* answer : {"", "", "0 90 100", "ani1.dat", ""})
        test::type(session, answer);
    session.handle(KeyEvent::typed(U'W'));
    session.handle(KeyEvent::typed(U'I'));
}

// Row `row` of a graphics screen as an 80x24 terminal shows it.
std::string shown_row(const ProgramScreen& screen, int row)
{
    return render_cells(screen.picture, {80, 24}, GlyphSet::ascii).row_text(row);
}

} // namespace

TEST_CASE("a caption takes the key-hint row of graphics mode and leaves the message line in view",
          "[session][captions]")
{
    MemoryFiles files;
    Session session({}, files);
    open_waypoint_editor(session, files);
    REQUIRE(session.screen().graphics);
    REQUIRE(test::message_of(session.screen().picture).starts_with("control point 2 of 3"));
    const ProgramScreen captioned = with_caption(session.screen(), "W opens the waypoint editor");
    // The message line is what it is without the caption; the caption is where the hints were.
    REQUIRE(shown_row(captioned, 18) == shown_row(session.screen(), 18));
    REQUIRE(shown_row(captioned, 18).starts_with(" control point 2 of 3"));
    REQUIRE(shown_row(captioned, 23).starts_with(" W opens the waypoint editor   "));
    REQUIRE(shown_row(session.screen(), 23).starts_with(" Tab point"));
    const CellGrid cells = render_cells(captioned.picture, {80, 24}, GlyphSet::ascii);
    REQUIRE(cells.style_at(0, 23) == CellStyle::reverse);
    REQUIRE(cells.style_at(79, 23) == CellStyle::reverse);
    REQUIRE(cells.style_at(1, 18) == CellStyle::plain);
    // The widest caption a script may hold fills the row and no more.
    const std::string widest(max_caption_columns, 'w');
    REQUIRE(shown_row(with_caption(session.screen(), widest), 23) == " " + widest);
}

TEST_CASE("on the text console a caption takes the bottom row, the console scrolled up when that row is in use",
          "[session][captions]")
{
    MemoryFiles files;
    files.files["key1.dat"] = "0 0 0\n0 6 0\n";
    files.files["key2.dat"] = "0 0 10\n0 6 10\n";
    Session session({}, files);
    const ProgramScreen text = with_caption(session.screen(), "Step 1: KEY1 is the first key frame");
    REQUIRE(text.text.row_text(23).starts_with(" Step 1: KEY1 is the first key frame   "));
    REQUIRE(text.text.style_at(0, 23) == CellStyle::reverse);
    REQUIRE(text.text.style_at(79, 23) == CellStyle::reverse);
    REQUIRE(text.text.row_text(0) == session.screen().text.row_text(0));
    REQUIRE(with_caption(session.screen(), "").text.row_text(23) == session.screen().text.row_text(23));
    // A console full to its last row: every row but the oldest stays in view, above the caption.
    for (int wrong = 0; wrong < 12; ++wrong)
        test::type(session, "missing.dat");
    const CellGrid full = session.screen().text;
    REQUIRE(full.row_text(23).find_first_not_of(' ') != std::string::npos);
    const CellGrid captioned = with_caption(session.screen(), "Step 1").text;
    for (int row = 1; row < 24; ++row)
        REQUIRE(captioned.row_text(row - 1) == full.row_text(row));
    REQUIRE(captioned.row_text(23).starts_with(" Step 1 "));
}

TEST_CASE("a caption longer than the row, as \"(skipped) \" makes the longest one, ends in \"...\" at the row's edge",
          "[session][captions]")
{
    ProgramScreen console;
    console.text = CellGrid(80, 24);
    // 79 columns, the most a script allows, and the verdict's 10 before it: 89.
    const std::string caption = "(skipped) " + std::string(71, 'a') + " the end";
    // The bar's space, then 76 columns of the caption and "...": the row's 80.
    REQUIRE(with_caption(console, caption).text.row_text(23) == " (skipped) " + std::string(66, 'a') + "...");
    // A caption that fits is whole.
    REQUIRE(with_caption(console, std::string(79, 'b')).text.row_text(23) == " " + std::string(79, 'b'));
}

TEST_CASE("a Thai caption keeps its combining marks on the caption row, in graphics mode and on the text console",
          "[session][captions]")
{
    // Issue 45 item 7: "สวัสดี" was shown as "สวสด".
    const std::string thai = "\u0E2A\u0E27\u0E31\u0E2A\u0E14\u0E35";
    MemoryFiles files;
    Session session({}, files);
    const ProgramScreen text = with_caption(session.screen(), "Step 1: " + thai);
    REQUIRE(text.text.row_text(23).starts_with(" Step 1: " + thai + "   "));
    REQUIRE(text.text.style_at(79, 23) == CellStyle::reverse);
    // Scrolled up under a later caption's row, it keeps them too.
    for (int wrong = 0; wrong < 12; ++wrong)
        test::type(session, "missing.dat");
    ProgramScreen full = session.screen();
    full.text.put_text(0, 23, thai);
    REQUIRE(with_caption(full, "x").text.row_text(22).starts_with(thai + " "));
    MemoryFiles graphics_files;
    Session graphics({}, graphics_files);
    open_waypoint_editor(graphics, graphics_files);
    REQUIRE(shown_row(with_caption(graphics.screen(), thai), 23).starts_with(" " + thai + "   "));
}

TEST_CASE("a caption wider than the key-hint row is refused with its file and line", "[session][captions]")
{
    const std::string widest(max_caption_columns, 'w');
    REQUIRE(parse_captioned_key_script("ENTER\n;; " + widest + "  \n", "class.keys"));
    const Expected<KeyScript> wide = parse_captioned_key_script("ENTER\nENTER ;; " + widest + "w\n", "class.keys");
    REQUIRE_FALSE(wide);
    REQUIRE(wide.error().to_string() ==
            "class.keys:2: expected a caption of at most 79 columns (the key-hint row of the 80x24 screen); found 80");
    // A wide character takes two columns of the row.
    const std::string chinese = "\xE5\x85\xB3\xE9\x94\xAE"; // two characters, four columns
    REQUIRE(parse_captioned_key_script(";; " + std::string(75, 'w') + chinese + "\n", "class.keys"));
    REQUIRE_FALSE(parse_captioned_key_script(";; " + std::string(76, 'w') + chinese + "\n", "class.keys"));
    // Plain ';' comments are not captions and may be as long as they like.
    REQUIRE(parse_captioned_key_script("; " + widest + widest + "\n", "class.keys"));
}

TEST_CASE("a TEXT line is one step of a paced replay — any other key is a step of its own", "[session][captions]")
{
    const Expected<KeyScript> script =
        parse_captioned_key_script("ENTER ENTER\nTEXT 0 90 100\nENTER\nTEXT ani1.dat\n4 J\nTEXT \n", "class.keys");
    REQUIRE(script);
    REQUIRE(script->events.size() == 2 + 8 + 1 + 8 + 2);
    REQUIRE(script->typed_lines == std::vector<TypedLine>{{2, 8}, {11, 8}});
    std::vector<std::string> steps;
    for (std::size_t first = 0; first < script->events.size(); first += step_length(*script, first))
        steps.push_back(step_label(*script, first));
    REQUIRE(steps == std::vector<std::string>{"ENTER", "ENTER", "TEXT 0 90 100", "ENTER", "TEXT ani1.dat", "4", "J"});
    REQUIRE(step_length(*script, script->events.size()) == 0);
    REQUIRE(step_label(*script, script->events.size()).empty());
}

TEST_CASE("the key just played is shown at the top right, clear of the message line", "[session][captions]")
{
    const CellGrid played = with_played_key(CellGrid(80, 24), "ENTER");
    REQUIRE(played.row_text(0) == std::string(67, ' ') + " key ENTER   ");
    REQUIRE(played.style_at(67, 0) == CellStyle::reverse);
    REQUIRE(played.style_at(78, 0) == CellStyle::plain);
    for (int row = 1; row < 24; ++row)
        REQUIRE(played.row_text(row) == std::string(80, ' '));
    // A long TEXT line is cut to the badge's width.
    const std::string cut = with_played_key(CellGrid(80, 24), "TEXT " + std::string(60, 'a')).row_text(0);
    REQUIRE(cut == std::string(46, ' ') + " key TEXT " + std::string(18, 'a') + "...   ");
    REQUIRE(with_played_key(CellGrid(80, 24), "") == CellGrid(80, 24));
    REQUIRE(with_played_key(CellGrid(8, 24), "ENTER") == CellGrid(8, 24));
}

TEST_CASE("a key script line that a terminal would obey is refused with its file and line", "[session][captions]")
{
    // Issue 45: a shared lesson's caption retitled the window and cleared the screen when echoed.
    const auto refusal = [](const std::string& text) {
        const Expected<KeyScript> script = parse_captioned_key_script(text, "class.keys");
        return script ? std::string("accepted") : script.error().to_string();
    };
    REQUIRE(refusal("ENTER\n;; hello \x1b]0;PWNED\x07\n") ==
            "class.keys:2: expected printable text; found the control character \\x1B (a terminal would obey it)");
    REQUIRE(refusal("TEXT way\x07" "1.dat\n") ==
            "class.keys:1: expected printable text; found the control character \\x07 (a terminal would obey it)");
    REQUIRE(refusal(";; \xc2\x9b" "2J\n") ==
            "class.keys:1: expected printable text; found the control character U+009B (a terminal would obey it)");
    // The review: a stray 0x9B, no UTF-8 at all, is CSI to a terminal in an 8-bit mode.
    REQUIRE(refusal(";; hi \x9b?1049h\n") ==
            "class.keys:1: expected printable text; found the control character \\x9B (a terminal would obey it)");
    // A continuation byte in 0x80-0x9F inside a valid sequence is no control: U+4E00 is E4 B8 80.
    REQUIRE(refusal(";; \xe4\xb8\x80\n") == "accepted");
    REQUIRE(refusal("GOAL VALUE TENSION 0.4 1\x7f\n") ==
            "class.keys:1: expected printable text; found the control character \\x7F (a terminal would obey it)");
    // A tab, line ends of either kind and text beyond ASCII stay.
    REQUIRE(refusal("ENTER\t6\r\n;; caf\xc3\xa9\r\n") == "accepted");
}
