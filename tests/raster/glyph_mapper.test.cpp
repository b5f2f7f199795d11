#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/painter.h"

#include <catch2/catch.hpp>

#include <string>
#include <string_view>

using namespace apcs;

namespace {

// One 9x14 cell, drawn, mapped to one ASCII character.
char32_t ascii_of(void (*draw)(Painter&))
{
    Bitmap cell(9, 14);
    Painter painter(cell);
    draw(painter);
    return map_to_cells(cell, {1, 1}, GlyphSet::ascii).at(0, 0);
}

} // namespace

TEST_CASE("ASCII glyph choices follow the shape of thin lines", "[raster][glyphs]")
{
    CHECK(ascii_of([](Painter& p) { p.line({0, 7}, {8, 7}); }) == U'-');
    CHECK(ascii_of([](Painter& p) { p.line({4, 0}, {4, 13}); }) == U'|');
    CHECK(ascii_of([](Painter& p) { p.line({0, 13}, {8, 0}); }) == U'/');
    CHECK(ascii_of([](Painter& p) { p.line({0, 0}, {8, 13}); }) == U'\\');
    CHECK(ascii_of([](Painter&) {}) == U' ');
}

TEST_CASE("no line shape is ever drawn with a mark's character, whatever the pixels", "[raster][glyphs]")
{
    // Every pattern of a 3x3 square and an x of 5x5 at each place in a cell, and the font's own
    // marks: none becomes x X o O * > a digit or a letter (SPEC §7.2: marks are reserved).
    for (const std::string_view drawn : {"x", "X", "o", "O", "*", ">", "#", "@", "1", "8"}) {
        Bitmap cell(9, 14);
        Painter(cell).text({0, 0}, std::string(drawn));
        const char32_t glyph = map_to_cells(cell, {1, 1}, GlyphSet::ascii).at(0, 0);
        CAPTURE(drawn, static_cast<std::uint32_t>(glyph));
        REQUIRE(std::u32string_view(U"xXoO*>0123456789#@$%&?").find(glyph) == std::u32string_view::npos);
        const bool letter = (glyph >= U'A' && glyph <= U'Z') || (glyph >= U'a' && glyph <= U'z');
        REQUIRE_FALSE(letter);
    }
    for (int x = 2; x < 7; ++x)
        for (int y = 2; y < 12; ++y) {
            Bitmap cell(9, 14);
            Painter(cell).cross_marker({x, y});
            const char32_t glyph = map_to_cells(cell, {1, 1}, GlyphSet::ascii).at(0, 0);
            REQUIRE(std::u32string_view(U"xXoO*>0123456789#@$%&?").find(glyph) == std::u32string_view::npos);
        }
}

TEST_CASE("the four corners of a frame are + in ascii at 80x24 and at 200x60, its sides lines", "[raster][glyphs]")
{
    // The session's boundary: the whole width, down to two pixels above text row 18.
    Bitmap raster;
    Painter(raster).rectangle({0, 0, 720, 259});
    for (const CellArea area : {CellArea{80, 24}, CellArea{200, 60}}) {
        const CellGrid grid = map_to_cells(raster, area, GlyphSet::ascii);
        const int bottom = cell_of_pixel(258, 348, area.rows);
        CAPTURE(area.columns);
        CHECK(grid.at(0, 0) == U'+');
        CHECK(grid.at(area.columns - 1, 0) == U'+');
        CHECK(grid.at(0, bottom) == U'+');
        CHECK(grid.at(area.columns - 1, bottom) == U'+');
        CHECK(grid.at(0, bottom / 2) == U'|');
        CHECK(grid.at(area.columns - 1, bottom / 2) == U'|');
        CHECK(std::u32string_view(U"-_").find(grid.at(area.columns / 2, 0)) != std::u32string_view::npos);
        CHECK(std::u32string_view(U"-_").find(grid.at(area.columns / 2, bottom)) != std::u32string_view::npos);
    }
}

TEST_CASE("a frame's top and bottom edges are each one line, one character from corner to corner, never =",
          "[raster][glyphs]")
{
    // At 200x60 a cell row is 5 or 6 pixels, fewer than the 7 pooled sub-rows: the top edge's one
    // pixel row fell in two sub-rows and read as '=' (the font's two bars pool so at 80x24).
    Bitmap raster;
    Painter(raster).rectangle({0, 0, 720, 259});
    for (const CellArea area : {CellArea{80, 24}, CellArea{100, 30}, CellArea{133, 40}, CellArea{200, 60},
                                CellArea{240, 72}}) {
        const CellGrid grid = map_to_cells(raster, area, GlyphSet::ascii);
        const int bottom = cell_of_pixel(258, 348, area.rows);
        CAPTURE(area.columns);
        for (const int row : {0, bottom}) {
            CAPTURE(row);
            const char32_t edge = grid.at(1, row);
            CHECK(std::u32string_view(U"-_").find(edge) != std::u32string_view::npos);
            for (int column = 1; column + 1 < area.columns; ++column)
                REQUIRE(grid.at(column, row) == edge);
        }
    }
}

TEST_CASE("a one-pixel line in a cell row shorter than 7 pixels is '-', where two lines in a 14-pixel row stay '='",
          "[raster][glyphs]")
{
    // 6 pixel rows: the line at the cell's top pixel row pools into sub-rows 0 and 1.
    Bitmap short_cell(9, 6);
    Painter(short_cell).line({0, 0}, {8, 0});
    CHECK(map_to_cells(short_cell, {1, 1}, GlyphSet::ascii).at(0, 0) == U'-');
    Bitmap cell(9, 14);
    Painter(cell).line({0, 5}, {8, 5});
    Painter(cell).line({0, 7}, {8, 7});
    CHECK(map_to_cells(cell, {1, 1}, GlyphSet::ascii).at(0, 0) == U'=');
}

TEST_CASE("a cell where a line turns at the cell's side is a corner, + — a straight line keeps its glyph", "[raster][glyphs]")
{
    CHECK(ascii_of([](Painter& p) { p.line({0, 0}, {8, 0}), p.line({0, 0}, {0, 13}); }) == U'+');
    CHECK(ascii_of([](Painter& p) { p.line({0, 13}, {8, 13}), p.line({8, 0}, {8, 13}); }) == U'+');
    CHECK(ascii_of([](Painter& p) { p.line({0, 7}, {8, 7}); }) == U'-');
    CHECK(ascii_of([](Painter& p) { p.line({0, 13}, {8, 13}); }) == U'_');
}

TEST_CASE("line-like symbols drawn in the font map back to themselves", "[raster][glyphs]")
{
    for (const char symbol : std::string_view("-|/\\_+^()[=.:")) {
        Bitmap cell(9, 14);
        Painter(cell).text({0, 0}, std::string(1, symbol));
        CAPTURE(symbol);
        REQUIRE(map_to_cells(cell, {1, 1}, GlyphSet::ascii).at(0, 0) == static_cast<char32_t>(symbol));
    }
}

TEST_CASE("a lit pixel anywhere in a cell never maps to a space", "[raster][glyphs]")
{
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille, GlyphSet::blocks}) {
        for (int y = 0; y < 14; ++y)
            for (int x = 0; x < 9; ++x) {
                Bitmap cell(9, 14);
                cell.set(x, y, true);
                REQUIRE(map_to_cells(cell, {1, 1}, glyphs).at(0, 0) != U' ');
            }
    }
}

TEST_CASE("braille dots and quadrant blocks map sub-blocks to the right bits", "[raster][glyphs]")
{
    Bitmap cell(2, 4);
    cell.set(0, 0, true); // dot 1
    cell.set(1, 3, true); // dot 8
    REQUIRE(map_to_cells(cell, {1, 1}, GlyphSet::braille).at(0, 0) == U'\u2881');
    Bitmap block(2, 2);
    block.set(1, 0, true);
    block.set(0, 1, true);
    REQUIRE(map_to_cells(block, {1, 1}, GlyphSet::blocks).at(0, 0) == U'\u259E');
}

TEST_CASE("the cell area keeps the 80x24 proportions from 80x24 on and needs at least 80x23", "[raster][glyphs]")
{
    REQUIRE_FALSE(fit_cell_area(79, 24).has_value());
    REQUIRE_FALSE(fit_cell_area(80, 22).has_value());
    REQUIRE(fit_cell_area(80, 24)->columns == 80);
    REQUIRE(fit_cell_area(80, 24)->rows == 24);
    REQUIRE(fit_cell_area(80, 25)->rows == 24);
    // 200x60 holds 80x24 scaled by 2.5 exactly.
    REQUIRE(fit_cell_area(200, 60)->columns == 200);
    REQUIRE(fit_cell_area(200, 60)->rows == 60);
    REQUIRE(fit_cell_area(160, 100)->columns == 160);
    REQUIRE(fit_cell_area(160, 100)->rows == 48);
}

TEST_CASE("a one-pixel path line survives the mapping at 80x24", "[raster][glyphs]")
{
    Bitmap bitmap;
    Painter(bitmap).line({5, 20}, {700, 300});
    const CellGrid grid = map_to_cells(bitmap, {80, 24}, GlyphSet::ascii);
    // Every column the line crosses shows something.
    for (int column = 1; column < 77; ++column) {
        bool seen = false;
        for (int row = 0; row < 24; ++row)
            seen = seen || grid.at(column, row) != U' ';
        CAPTURE(column);
        REQUIRE(seen);
    }
}

TEST_CASE("the cell of a pixel follows the mapping's partition", "[raster][glyphs]")
{
    // 348 rows on 30 cells: cell 25 covers 290 … 300, cell 26 starts at 301.
    REQUIRE(cell_of_pixel(289, 348, 30) == 24);
    REQUIRE(cell_of_pixel(290, 348, 30) == 25);
    REQUIRE(cell_of_pixel(300, 348, 30) == 25);
    REQUIRE(cell_of_pixel(301, 348, 30) == 26);
    for (int x = 0; x < 720; ++x)
        REQUIRE(cell_of_pixel(x, 720, 80) == x / 9);
    for (int y = 0; y < 348; ++y) {
        Bitmap bitmap(720, 348);
        bitmap.set(5, y, true);
        const CellGrid grid = map_to_cells(bitmap, {96, 30}, GlyphSet::blocks);
        REQUIRE(grid.at(0, cell_of_pixel(y, 348, 30)) != U' ');
    }
}
