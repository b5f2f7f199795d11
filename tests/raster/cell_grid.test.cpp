#include "apcs/raster/cell_grid.h"

#include <catch2/catch.hpp>

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
