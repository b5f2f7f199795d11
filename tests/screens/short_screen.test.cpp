#include "apcs/screens/short_screen.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/path_screen.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

namespace {

// A path screen with every text row filled: a region picked on a bent path, its message, the staff
// and the key-hint row.
GraphicsScreen full_path_screen()
{
    ControlPoints points;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{2, 6, 1}, Vec3{5, 1, 3}, Vec3{9, 8, 2}})
        points.push_back({position, {0.5, -1, 0, 0.25}});
    static EvaluatedPath path;
    path = evaluate_path(points, {{}, 32, 12, Spacing::nearest});
    PathScreenContent content = path_screen_content(points, path);
    content.region = ControlRegion{1, 2};
    content.active_line = StaffLine::bias;
    content.message = "way1.dat: BIAS  control points 2 to 3 of 4";
    content.key_help = "4/6 step  J/L 3 steps  Enter accept  Esc keep  ? help";
    const ViewTransform view = path_screen_scene(content).fit({20, 60}, layout::view_area);
    return draw_path_screen(content, view);
}

// The rows of `grid` from `first` on, `count` of them, as text.
std::string rows_text(const CellGrid& grid, int first, int count)
{
    std::string text;
    for (int row = first; row < first + count; ++row)
        text += grid.row_text(row) + "\n";
    return text;
}

bool blank(const CellGrid& grid, int row)
{
    return grid.row_text(row).find_first_not_of(' ') == std::string::npos;
}

} // namespace

TEST_CASE("a terminal of 80x23 shows the short screen and one row less is refused", "[screen][short]")
{
    REQUIRE(fit_cell_area(80, 23)->columns == 80);
    REQUIRE(fit_cell_area(80, 23)->rows == 23);
    // Wider still: the text is 80 columns, and 23 rows leave no room for a larger area.
    REQUIRE(fit_cell_area(200, 23)->columns == 80);
    REQUIRE(fit_cell_area(200, 23)->rows == 23);
    REQUIRE(is_short_area(*fit_cell_area(80, 23)));
    REQUIRE_FALSE(is_short_area(*fit_cell_area(80, 24)));
    REQUIRE_FALSE(fit_cell_area(79, 23).has_value());
    REQUIRE_FALSE(fit_cell_area(80, 22).has_value());
}

TEST_CASE("the short screen keeps every raster row in order: the drawing in 17 text rows and each text row one up",
          "[screen][short]")
{
    const auto text_row = [](int y) { return cell_of_pixel(y, hercules::screen_height, text_screen_rows); };
    int previous = 0;
    for (int y = 0; y < hercules::screen_height; ++y) {
        const int moved = short_screen_y(y);
        CAPTURE(y, moved);
        REQUIRE(moved >= previous);
        REQUIRE(moved <= y);
        previous = moved;
        if (y < hercules::text_row_top(layout::message_row))
            REQUIRE(text_row(moved) < layout::message_row - 1);
        else
            REQUIRE(text_row(moved) == text_row(y) - 1);
    }
    // The top and bottom of the drawing area reach its first and last rows on the short screen, and
    // the view inside keeps its margin of one row: nothing it places lands on the boundary.
    REQUIRE(text_row(short_screen_y(0)) == 0);
    REQUIRE(text_row(short_screen_y(layout::drawing_area.bottom)) == layout::message_row - 2);
    REQUIRE(text_row(short_screen_y(layout::view_area.top)) == 1);
    REQUIRE(text_row(short_screen_y(layout::view_area.bottom)) == layout::message_row - 3);
    // The 24th text row's raster rows are left empty.
    REQUIRE(short_screen_y(hercules::screen_height - 1) < hercules::text_row_top(text_screen_rows - 1));
}

TEST_CASE("at 80x23 every text row of the path screen stays as at 80x24 and the drawing gives up one row",
          "[screen][short]")
{
    const GraphicsScreen screen = full_path_screen();
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille, GlyphSet::blocks}) {
        const CellGrid full = render_cells(screen, {80, 24}, glyphs);
        const CellGrid short_grid = render_screen_cells(screen, {80, 23}, glyphs);
        CAPTURE(static_cast<int>(glyphs));
        INFO("80x24:\n" << full.to_text() << "80x23:\n" << short_grid.to_text());
        REQUIRE(short_grid.columns() == 80);
        REQUIRE(short_grid.rows() == 23);
        // Message, four staff lines and key hint: the same characters, styles and colours, a row up.
        const int text_rows = text_screen_rows - layout::message_row;
        REQUIRE(rows_text(short_grid, layout::message_row - 1, text_rows) ==
                rows_text(full, layout::message_row, text_rows));
        for (int row = layout::message_row - 1; row < short_grid.rows(); ++row)
            for (int column = 0; column < 80; ++column) {
                REQUIRE(short_grid.style_at(column, row) == full.style_at(column, row + 1));
                REQUIRE(short_grid.role_at(column, row) == full.role_at(column, row + 1));
            }
        REQUIRE(short_grid.row_text(layout::message_row - 1).find("BIAS") != std::string::npos);
        REQUIRE(short_grid.row_text(layout::key_help_row - 1).find("? help") != std::string::npos);
        // The drawing's boundary: its top line in row 0, its bottom line in row 16 (17 rows, one
        // fewer than 80x24's 18), every row between them showing its sides.
        REQUIRE(short_grid.row_text(0).find_first_not_of(' ') == 0);
        REQUIRE(short_grid.at(0, layout::message_row - 2) != U' ');
        REQUIRE(short_grid.at(40, layout::message_row - 2) != U' ');
        for (int row = 0; row < layout::message_row - 1; ++row) {
            CAPTURE(row);
            REQUIRE(short_grid.at(0, row) != U' ');
            REQUIRE(short_grid.at(79, row) != U' ');
        }
        // The view's margin: no control point on the boundary's top or bottom row.
        for (const int row : {0, layout::message_row - 2})
            REQUIRE(short_grid.row_text(row).find('x') == std::string::npos);
    }
}

TEST_CASE("the short screen shows as many control points and picked ones as 80x24", "[screen][short]")
{
    const GraphicsScreen screen = full_path_screen();
    const auto count = [](const CellGrid& grid, int rows, char32_t glyph, bool picked) {
        int found = 0;
        for (int row = 0; row < rows; ++row)
            for (int column = 0; column < grid.columns(); ++column)
                if (grid.at(column, row) == glyph && (grid.style_at(column, row) == CellStyle::reverse) == picked)
                    ++found;
        return found;
    };
    const CellGrid full = render_cells(screen, {80, 24}, GlyphSet::ascii);
    const CellGrid short_grid = render_screen_cells(screen, {80, 23}, GlyphSet::ascii);
    // Two control points outside the region, two in it, each an x of its own cell.
    REQUIRE(count(full, layout::message_row, U'x', false) == 2);
    REQUIRE(count(full, layout::message_row, U'x', true) == 2);
    REQUIRE(count(short_grid, layout::message_row - 1, U'x', false) == 2);
    REQUIRE(count(short_grid, layout::message_row - 1, U'x', true) == 2);
}

TEST_CASE("a text screen on 23 rows leaves out its first blank row or else its oldest line", "[screen][short]")
{
    CellGrid help(80, 24);
    help.put_text(0, 0, "APCS help - the keys of the staff");
    for (int row = 2; row < 24; ++row)
        help.put_text(0, row, "  line " + std::to_string(row));
    const CellGrid shown = text_on_short_screen(help);
    REQUIRE(shown.rows() == 23);
    REQUIRE(shown.row_text(0) == help.row_text(0));
    for (int row = 1; row < 23; ++row)
        REQUIRE(shown.row_text(row) == help.row_text(row + 1));

    CellGrid console(80, 24);
    for (int row = 0; row < 24; ++row)
        console.put_text(0, row, "console line " + std::to_string(row), row == 23 ? CellStyle::reverse : CellStyle::plain);
    const CellGrid scrolled = text_on_short_screen(console);
    REQUIRE(scrolled.rows() == 23);
    REQUIRE(scrolled.row_text(0).starts_with("console line 1 "));
    REQUIRE(scrolled.row_text(22).starts_with("console line 23"));
    REQUIRE(scrolled.style_at(0, 22) == CellStyle::reverse);
    REQUIRE_FALSE(blank(scrolled, 21));
}
