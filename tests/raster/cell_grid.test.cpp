#include "apcs/raster/cell_grid.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

using namespace apcs;

TEST_CASE("cell widths are Unicode's: wide CJK and fullwidth 2, combining 0, controls -1", "[raster][cells]")
{
    REQUIRE(cell_width(U'a') == 1);
    REQUIRE(cell_width(U'\u00E9') == 1);  // é
    REQUIRE(cell_width(U'\u2588') == 1);  // full block, a glyph of the pictures
    REQUIRE(cell_width(U'\u6F22') == 2);  // 漢
    REQUIRE(cell_width(U'\uFF21') == 2);  // fullwidth A
    REQUIRE(cell_width(U'\u0301') == 0);  // combining acute accent
    REQUIRE(cell_width(U'\u200B') == 0);  // zero-width space
    REQUIRE(cell_width(U'\u0007') == -1); // bell
}

TEST_CASE("a wide character fills two cells and the row reads as the terminal shows it", "[raster][cells]")
{
    CellGrid grid(8, 1);
    grid.put_text(0, 0, "a\u6F22b");
    REQUIRE(grid.at(0, 0) == U'a');
    REQUIRE(grid.at(1, 0) == U'\u6F22');
    REQUIRE(grid.at(2, 0) == CellGrid::wide_tail);
    REQUIRE(grid.at(3, 0) == U'b');
    REQUIRE(grid.row_text(0) == "a\u6F22b    ");
}

TEST_CASE("zero-width and control characters take no cell: a combining mark joins its character's", "[raster][cells]")
{
    CellGrid grid(4, 1);
    grid.put_text(0, 0, "e\u0301\tx");
    REQUIRE(grid.row_text(0) == "e\u0301x  ");
    REQUIRE(grid.marks_at(0, 0) == U"\u0301");
    REQUIRE(grid.at(1, 0) == U'x');
    // A mark with no character before it in the text has no cell to join, and is left out.
    grid.put_text(2, 0, "\u0301y");
    REQUIRE(grid.row_text(0) == "e\u0301xy ");
    // Writing over a cell clears its marks.
    grid.put_text(0, 0, "a");
    REQUIRE(grid.row_text(0) == "axy ");
}

TEST_CASE("a Thai caption keeps its vowel and tone marks in the cells of its letters", "[raster][cells][captions]")
{
    // Issue 45 item 7: "สวัสดี" showed as "สวสด": the zero-width marks were dropped.
    CellGrid grid(6, 1);
    grid.put_text(0, 0, "\u0E2A\u0E27\u0E31\u0E2A\u0E14\u0E35");
    REQUIRE(grid.row_text(0) == "\u0E2A\u0E27\u0E31\u0E2A\u0E14\u0E35  ");
    REQUIRE(grid.marks_at(1, 0) == U"\u0E31");
    REQUIRE(grid.marks_at(3, 0) == U"\u0E35");
    REQUIRE(grid.at(4, 0) == U' ');
    // More marks than a terminal's cell holds (ncurses: four) are left out.
    CellGrid heaped(2, 1);
    heaped.put_text(0, 0, "a\u0301\u0302\u0303\u0304\u0305b");
    REQUIRE(heaped.row_text(0) == "a\u0301\u0302\u0303\u0304b");
}

TEST_CASE("a wide character that the right edge would cut in half is left out", "[raster][cells]")
{
    CellGrid grid(3, 1);
    grid.put_text(0, 0, "ab\u6F22");
    REQUIRE(grid.row_text(0) == "ab ");
}

TEST_CASE("writing over half of a wide character blanks its other half", "[raster][cells]")
{
    CellGrid grid(4, 2);
    grid.put_text(0, 0, "\u6F22\u5B57");
    grid.set(1, 0, U'x');
    REQUIRE(grid.row_text(0) == " x\u5B57");
    grid.put_text(0, 1, "\u6F22\u5B57");
    grid.put_text(0, 1, "yz");
    REQUIRE(grid.row_text(1) == "yz\u5B57");
}

namespace {

// xterm's default 16 colours (its XTerm-col.ad resource file: color0 … color15).
constexpr std::array<std::uint32_t, 16> xterm_palette = {
    0x000000, 0xcd0000, 0x00cd00, 0xcdcd00, 0x0000ee, 0xcd00cd, 0x00cdcd, 0xe5e5e5,
    0x7f7f7f, 0xff0000, 0x00ff00, 0xffff00, 0x5c5cff, 0xff00ff, 0x00ffff, 0xffffff,
};

// WCAG 2's relative luminance of an sRGB colour 0xRRGGBB.
double relative_luminance(std::uint32_t rgb)
{
    const auto linear = [](std::uint32_t channel) {
        const double value = channel / 255.0;
        return value <= 0.04045 ? value / 12.92 : std::pow((value + 0.055) / 1.055, 2.4);
    };
    return 0.2126 * linear(rgb >> 16 & 0xff) + 0.7152 * linear(rgb >> 8 & 0xff) + 0.0722 * linear(rgb & 0xff);
}

// WCAG 2's contrast ratio of a colour against black.
double contrast_on_black(std::uint32_t rgb) { return (relative_luminance(rgb) + 0.05) / 0.05; }

} // namespace

TEST_CASE("every colour role stands at least 4.5:1 against black in xterm's default palette", "[raster][colour]")
{
    // The figures SPEC §3.2 gives, so that the table's formula is the one it measured with.
    REQUIRE(contrast_on_black(xterm_palette[4]) == Approx(2.2).margin(0.05));  // blue
    REQUIRE(contrast_on_black(xterm_palette[1]) == Approx(3.6).margin(0.05));  // red
    REQUIRE(contrast_on_black(xterm_palette[5]) == Approx(4.48).margin(0.01)); // magenta
    REQUIRE(contrast_on_black(xterm_palette[12]) == Approx(4.4).margin(0.05)); // bright blue
    for (const ColourRole role : colour_roles) {
        const int number = colour_number(role);
        CAPTURE(colour_role_name(role), colour_name(role), number);
        if (number < 0) // the terminal's own foreground, or reverse video: no colour of ours
            continue;
        REQUIRE(number < 16);
        CHECK(contrast_on_black(xterm_palette[static_cast<std::size_t>(number)]) >= 4.5);
    }
}

TEST_CASE("a character is appended within a byte limit whole or not at all", "[raster][cells]")
{
    std::string text(198, 'a');
    REQUIRE_FALSE(append_utf8_within(text, U'\u6F22', 200)); // 3 bytes: 201
    REQUIRE(text.size() == 198);
    REQUIRE(append_utf8_within(text, U'\u00E9', 200)); // 2 bytes: 200
    REQUIRE(text.size() == 200);
    REQUIRE(text.ends_with("\xC3\xA9"));
    REQUIRE_FALSE(append_utf8_within(text, U'b', 200));
    REQUIRE(text.size() == 200);
}

TEST_CASE("text fitted to a number of columns is whole, or its first characters and \"...\" in them",
          "[raster][cells]")
{
    REQUIRE(fitted_to_columns("abc", 3) == "abc");
    REQUIRE(fitted_to_columns("abcdef", 5) == "ab...");
    // 漢字漢字 takes 8 columns: in 6, 3 are left before "...", where the second 漢 (columns 3-4)
    // does not fit whole.
    REQUIRE(fitted_to_columns("\u6F22\u5B57\u6F22\u5B57", 6) == "\u6F22...");
    REQUIRE(text_columns(fitted_to_columns("\u6F22\u5B57\u6F22\u5B57", 7)) == 7); // 漢字...
    REQUIRE(fitted_to_columns("abcdef", 2) == "..");
}
