#include "apcs/session/path_screen.h"
#include "apcs/session/screen_layout.h"

#include "support/golden.h"

#include <catch2/catch.hpp>

using namespace apcs;

namespace {

struct Example {
    ControlPoints points;
    EvaluatedPath path;
    GraphicsScreen screen;
};

Example example_screen()
{
    Example example;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{3, -4, 5}, Vec3{0, 0, 10}})
        example.points.push_back({position, {0.25, 0, -0.5, 0}});
    example.path = evaluate_path(example.points, {{}, 32, 12, Spacing::nearest});
    PathScreenContent content = path_screen_content(example.points, example.path);
    content.active_line = StaffLine::continuity;
    content.message = "4/6 step  J/L 3 steps  Enter accept  Esc keep";
    const ViewTransform view = path_screen_scene(content).fit({30, 40}, layout::drawing_area);
    example.screen = draw_path_screen(content, view);
    return example;
}

} // namespace

TEST_CASE("the path screen in each glyph set matches its approved cell grid", "[session][screen]")
{
    const Example example = example_screen();
    test::check_golden("path_screen_ascii.txt", render_cells(example.screen, {80, 25}, GlyphSet::ascii).to_text());
    test::check_golden("path_screen_braille.txt", render_cells(example.screen, {80, 25}, GlyphSet::braille).to_text());
    test::check_golden("path_screen_blocks.txt", render_cells(example.screen, {80, 25}, GlyphSet::blocks).to_text());
}

TEST_CASE("the path screen shows the staff values and the active line", "[session][screen]")
{
    const CellGrid grid = render_cells(example_screen().screen, {80, 25}, GlyphSet::ascii);
    REQUIRE(grid.row_text(19).starts_with(" TENSION"));
    REQUIRE(grid.row_text(20).starts_with(">CONTINUITY"));
    REQUIRE(grid.row_text(19).substr(69, 5) == "+0.25");
    REQUIRE(grid.row_text(21).substr(69, 5) == "-0.50");
}

TEST_CASE("every control point shows as x in the cells", "[session][screen]")
{
    const Example example = example_screen();
    std::size_t crosses = 0;
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille}) {
        const CellGrid grid = render_cells(example.screen, {80, 25}, glyphs);
        crosses = 0;
        for (int row = 0; row < 18; ++row)
            for (int column = 0; column < 80; ++column)
                crosses += grid.at(column, row) == U'x' ? 1u : 0u;
        REQUIRE(crosses == 3);
    }
}

TEST_CASE("staff values are shown with a sign and two decimals", "[session][screen]")
{
    REQUIRE(format_staff_value(0.0) == "+0.00");
    REQUIRE(format_staff_value(-0.0000001) == "+0.00");
    REQUIRE(format_staff_value(0.05) == "+0.05");
    REQUIRE(format_staff_value(-1.0) == "-1.00");
}
