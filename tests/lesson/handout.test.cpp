#include "apcs/lesson/handout.h"
#include "apcs/raster/painter.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

TEST_CASE("a caption's short name keeps its letters and digits, lowercased, words joined by '-'",
          "[session][handout]")
{
    const auto [caption, name] = GENERATE(table<std::string, std::string>({
        {"W opens the waypoint editor; I inserts a control point halfway along the path",
         "w-opens-the-waypoint-editor-i"},
        {"= types an exact value: tension 0.5 shortens both tangents", "types-an-exact-value-tension-0-5"},
        {"U undoes", "u-undoes"},
        {"  -- Bias +0.5 --  ", "bias-0-5"},
        {"Überblick", "berblick"},
        {"→ … ;", "caption"},
        {"", "caption"},
        {std::string(40, 'a'), std::string(32, 'a')},
        {"abcdefghijklmnopqrstuvwxyzabcdef ghi", "abcdefghijklmnopqrstuvwxyzabcdef"},
    }));
    CAPTURE(caption);
    const std::string shown = handout_step_name(caption);
    REQUIRE(shown == name);
    REQUIRE(shown.size() <= max_step_name_length);
}

TEST_CASE("a handout page's name is the caption's number from 01 and its short name", "[session][handout]")
{
    REQUIRE(handout_file_stem(1, 12, "T shows the tangents") == "01-t-shows-the-tangents");
    REQUIRE(handout_file_stem(12, 12, "U") == "12-u");
    REQUIRE(handout_file_stem(100, 100, "U") == "100-u");
    // Issue 45: with 100 captions or more every page takes the same width, so names sort in order.
    REQUIRE(handout_file_stem(1, 100, "U") == "001-u");
    REQUIRE(handout_file_stem(99, 1000, "U") == "0099-u");
    REQUIRE(handout_file_stem(7, 9, "U") == "07-u");
}

TEST_CASE("a handout's folder holds its index, its pages and what was kept of them, nothing of the user's",
          "[session][handout]")
{
    const auto [name, page, of_handout] = GENERATE(table<std::string, bool, bool>({
        {"01-w-opens-the-waypoint-editor-i.png", true, true},
        {"100-caption.txt", true, true},
        {"01-caption.bak", false, true},
        {"01-caption.b07", false, true},
        {"index.html", false, true},
        {"index.bak", false, true},
        {"index.b01", false, true},
        {".01-caption.png.a1B2c3", false, true},
        {"index.htm", false, false},
        {"notes.txt", false, false},
        {"1-caption.png", false, false},
        {"01-Caption.png", false, false},
        {"01-caption.pdf", false, false},
        {"01-.png", false, false},
        {"01-caption.bak.bak", false, false},
        {"index.b1x", false, false},
    }));
    CAPTURE(name);
    CHECK(is_handout_page_name(name) == page);
    CHECK(is_handout_file_name(name) == of_handout);
}

TEST_CASE("the text console's page is its rows drawn in the font, graphics mode's its picture", "[session][handout]")
{
    ProgramScreen console;
    console.text = CellGrid(80, 24);
    console.text.put_text(0, 0, "Please keyin the KEY1 filename!");
    console.text.put_text(0, 23, " a caption", CellStyle::reverse);
    const GraphicsScreen picture = screen_picture(console);
    REQUIRE(picture.text.size() == 2);
    REQUIRE(picture.text[0].row == 0);
    REQUIRE(picture.text[0].text == "Please keyin the KEY1 filename!");
    REQUIRE(picture.text[1].row == 23);
    REQUIRE(picture.text[1].text == " a caption");
    REQUIRE(screen_text(console, GlyphSet::ascii) ==
            "Please keyin the KEY1 filename!\n" + std::string(22, '\n') + " a caption\n");
}

TEST_CASE("a handout page keeps a Thai caption's combining marks: in its text, and its picture in the caption's columns",
          "[session][handout]")
{
    // Issue 45 item 7: the handout's text had "สวสด" for "สวัสดี". Its picture is drawn in the VGA
    // font, which has no Thai: each letter is a '?' there (manual section 12), and a mark takes no
    // cell of its own, so what follows stays in its column.
    const std::string thai = "\u0E2A\u0E27\u0E31\u0E2A\u0E14\u0E35";
    ProgramScreen console;
    console.text = CellGrid(80, 24);
    const std::string caption = " " + thai + " x";
    console.text.put_text(0, 23, caption, CellStyle::reverse);
    // Not std::string(23, '\n') + caption: GCC 12 at -O1 warns falsely of that temporary's bounds.
    std::string console_text(23, '\n');
    console_text += caption + "\n";
    REQUIRE(screen_text(console, GlyphSet::ascii) == console_text);
    const GraphicsScreen picture = screen_picture(console);
    REQUIRE(picture.text.size() == 1);
    REQUIRE(picture.text[0].text == " " + thai + " x");
    Bitmap drawn(80 * 9, 14);
    Painter(drawn).text({0, 0}, picture.text[0].text);
    Bitmap expected(80 * 9, 14);
    Painter(expected).text({0, 0}, " ???? x");
    REQUIRE(drawn == expected);
}

TEST_CASE("an empty prompt is the text console with a question and nothing typed", "[session][handout]")
{
    ProgramScreen console;
    console.text = CellGrid(80, 24);
    REQUIRE(is_empty_prompt(console));
    console.text.put_text(0, 0, "Please keyin the KEY1 filename!");
    console.text.put_text(0, 1, "_");
    REQUIRE(is_empty_prompt(console));
    // An answer begun, or a second line of text (what the earlier steps printed), is not empty.
    ProgramScreen typed = console;
    typed.text.put_text(0, 1, "key1.dat_");
    REQUIRE_FALSE(is_empty_prompt(typed));
    ProgramScreen answered = console;
    answered.text.put_text(0, 0, "Please keyin the KEY1 filename!");
    answered.text.put_text(0, 1, "key1.dat");
    answered.text.put_text(0, 2, "Please keyin the KEY2 filename!");
    answered.text.put_text(0, 3, "_");
    REQUIRE_FALSE(is_empty_prompt(answered));
    // Graphics mode is never an empty prompt, whatever it shows.
    ProgramScreen graphics;
    graphics.graphics = true;
    REQUIRE_FALSE(is_empty_prompt(graphics));
}
