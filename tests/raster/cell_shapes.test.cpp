// SPEC §7.2, §7.2.1: tangent arrows and the picked region's box are laid as characters, so that
// they read at 80x24 in every glyph set without colour.
#include "apcs/raster/graphics_screen.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

namespace {

// Row `row` of the 80x24 cells, columns `first` to `last`.
std::string cells(const CellGrid& grid, int row, int first, int last)
{
    CellGrid line(last - first + 1, 1);
    for (int column = first; column <= last; ++column)
        line.set(column - first, 0, grid.at(column, row));
    return line.row_text(0);
}

// A control point at pixel (90, 100) (cell 10, 6) with DD leaving it to the right, solid, to
// pixel 180 (cell 20), and a dashed DS from pixel (90, 120) (cell 10, 8) to (180, 120).
GraphicsScreen two_arrows()
{
    GraphicsScreen screen;
    screen.marks.push_back({{90, 100}, MarkKind::control_point});
    screen.arrows.push_back({{90, 100}, {180, 100}, LineStyle::solid, ColourRole::tangent});
    screen.arrows.push_back({{90, 120}, {180, 120}, LineStyle::dashed, ColourRole::tangent});
    return screen;
}

} // namespace

TEST_CASE("a solid and a dashed tangent arrow differ in glyph and end in a head in every glyph set",
          "[raster][tangents]")
{
    const GraphicsScreen screen = two_arrows();
    const CellGrid ascii = render_cells(screen, {80, 24}, GlyphSet::ascii);
    // The control point keeps its cell; the solid line fills every cell up to the head.
    REQUIRE(cells(ascii, 6, 10, 20) == "x--------->");
    // Dashed: every other cell, counted back from the head.
    REQUIRE(cells(ascii, 8, 10, 20) == "- - - - - >");
    for (const GlyphSet glyphs : {GlyphSet::braille, GlyphSet::blocks}) {
        const CellGrid grid = render_cells(screen, {80, 24}, glyphs);
        REQUIRE(cells(grid, 6, 10, 20) == "x─────────→");
        REQUIRE(cells(grid, 8, 10, 20) == "┄ ┄ ┄ ┄ ┄ ⇒");
    }
}

TEST_CASE("an arrow's head points its way: up, down and the slants", "[raster][tangents]")
{
    GraphicsScreen screen;
    screen.arrows.push_back({{90, 200}, {90, 100}, LineStyle::solid, ColourRole::tangent});   // up, cells 13 to 6
    screen.arrows.push_back({{300, 100}, {300, 200}, LineStyle::solid, ColourRole::tangent}); // down
    screen.arrows.push_back({{500, 200}, {560, 150}, LineStyle::solid, ColourRole::tangent}); // up and right
    const CellGrid braille = render_cells(screen, {80, 24}, GlyphSet::braille);
    REQUIRE(braille.at(10, 6) == U'\u2191');
    REQUIRE(braille.at(10, 7) == U'\u2502');
    REQUIRE(braille.at(33, 13) == U'\u2193');
    REQUIRE(braille.at(62, 10) == U'\u2197');
    const CellGrid ascii = render_cells(screen, {80, 24}, GlyphSet::ascii);
    REQUIRE(ascii.at(10, 6) == U'^');
    REQUIRE(ascii.at(33, 13) == U'v');
    REQUIRE(ascii.at(62, 10) == U'>');
}

TEST_CASE("a box is laid on the cells its rectangle's edges fall in and leaves the marks inside", "[raster][region]")
{
    GraphicsScreen screen;
    screen.marks.push_back({{135, 120}, MarkKind::control_point, CellStyle::reverse, ColourRole::region});
    screen.boxes.push_back({90, 100, 180, 145}); // cells 10 to 20, rows 6 to 10
    const CellGrid ascii = render_cells(screen, {80, 24}, GlyphSet::ascii);
    REQUIRE(cells(ascii, 6, 10, 20) == "+---------+");
    REQUIRE(cells(ascii, 8, 10, 20) == "|    x    |");
    REQUIRE(cells(ascii, 10, 10, 20) == "+---------+");
    const CellGrid braille = render_cells(screen, {80, 24}, GlyphSet::braille);
    REQUIRE(cells(braille, 6, 10, 20) == "┌─────────┐");
    REQUIRE(cells(braille, 10, 10, 20) == "└─────────┘");
}
