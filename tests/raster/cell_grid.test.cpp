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

TEST_CASE("zero-width and control characters take no cell", "[raster][cells]")
{
    CellGrid grid(4, 1);
    grid.put_text(0, 0, "e\u0301\tx");
    REQUIRE(grid.row_text(0) == "ex  ");
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
