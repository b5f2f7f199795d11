// SPEC §7.2.1's colour: the 1989 elements in the monitor's one colour, each overlay in its own role,
// decided where the layer is painted; NO_COLOR and --color never give one colour.
#include "apcs/cli/session_command.h"
#include "apcs/input/key_map.h"
#include "apcs/editor/path_editor.h"

#include "support/golden.h"
#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace apcs;
using apcs::test::apply;
using apcs::test::LogLines;
namespace cmd = apcs::command;

namespace {

// The zigzag of path_teaching, with a key frame (a square) beside it for K.
PathEditor::Setup zigzag_with_key_frame()
{
    PathEditor::Setup setup = apcs::test::path_setup({Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{2, 2, 0}, Vec3{4, 2, 0}},
                                                     {{1, 1}, 16, 5, Spacing::exact});
    setup.view_angles = {-90.0, 0.0};
    setup.key_frame_polylines = {{Vec3{0.5, 2, 0}, Vec3{1.5, 2, 0}, Vec3{1.5, 3, 0}, Vec3{0.5, 3, 0}, Vec3{0.5, 2, 0}}};
    return setup;
}

// The path screen with K on, after a staff step (the ghost), with T and G on. Under global control
// every control point is in the picked region.
GraphicsScreen every_overlay()
{
    LogLines log;
    PathEditor editor(zigzag_with_key_frame(), log);
    // K first: showing the key frames fits the view again, which drops the ghost.
    apply(editor, {cmd::ToggleKeyFrames{}, cmd::ChooseGlobal{}, cmd::Accept{}, cmd::StaffStep{+10},
                   cmd::ToggleTangents{}, cmd::ToggleLawGraph{}});
    return editor.view();
}

std::size_t cells_of(const CellGrid& grid, ColourRole role)
{
    const std::string roles = grid.roles_text();
    return static_cast<std::size_t>(std::count(roles.begin(), roles.end(), colour_letter(role)));
}

} // namespace

TEST_CASE("each overlay of the path screen is drawn in its own colour role, the 1989 ones in the monitor's",
          "[session][colour]")
{
    const GraphicsScreen screen = every_overlay();
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille}) {
        const CellGrid grid = render_cells(screen, {80, 24}, glyphs);
        for (const ColourRole role : {ColourRole::tangent, ColourRole::law, ColourRole::key_frame, ColourRole::ghost,
                                      ColourRole::inbetween}) {
            CAPTURE(glyphs, colour_letter(role));
            REQUIRE(cells_of(grid, role) > 0);
        }
        for (int row = 0; row < grid.rows(); ++row)
            for (int column = 0; column < grid.columns(); ++column) {
                const char32_t glyph = grid.at(column, row);
                CAPTURE(row, column);
                // The staff's value marks and every row below the drawing are the monitor's; an x is
                // the region's exactly when it is in reverse video.
                if (glyph == U'O' || row >= 18)
                    REQUIRE(grid.role_at(column, row) == ColourRole::monitor);
                if (glyph == U'x')
                    REQUIRE((grid.role_at(column, row) == ColourRole::region) ==
                            (grid.style_at(column, row) == CellStyle::reverse));
                if (glyph == U'+' && row < 18 && glyphs == GlyphSet::braille) // ascii draws corners with +
                    REQUIRE((grid.role_at(column, row) == ColourRole::tangent ||
                             grid.role_at(column, row) == ColourRole::law));
            }
    }
}

TEST_CASE("a pixel two layers light shows the role of higher priority, whatever the order they were painted in",
          "[session][colour]")
{
    Bitmap one;
    one.set(10, 10, true);
    for (const bool curve_first : {true, false}) {
        GraphicsScreen screen;
        if (curve_first)
            paint_layer(screen, one, ColourRole::monitor);
        paint_layer(screen, one, ColourRole::ghost);
        if (!curve_first)
            paint_layer(screen, one, ColourRole::monitor);
        paint_layer(screen, one, ColourRole::key_frame);
        REQUIRE(pixel_role(screen, 10, 10) == ColourRole::monitor);
        paint_layer(screen, one, ColourRole::tangent);
        REQUIRE(pixel_role(screen, 10, 10) == ColourRole::tangent);
        REQUIRE(render_cells(screen, {80, 24}, GlyphSet::braille).role_at(1, 0) == ColourRole::tangent);
    }
}

TEST_CASE("the picked region's x marks carry the region's role", "[session][colour]")
{
    const std::vector<ControlPointRun> runs{{{100, 100}, 0, 0}, {{200, 100}, 1, 1}, {{300, 100}, 2, 2}};
    const std::vector<PixelMark> marks = control_point_marks(runs, ControlRegion{1, 2});
    for (const PixelMark& mark : marks)
        REQUIRE((mark.role == ColourRole::region) == (mark.style == CellStyle::reverse));
    REQUIRE(std::count_if(marks.begin(), marks.end(), [](const PixelMark& mark) { return mark.role == ColourRole::region; }) == 2);
}

TEST_CASE("the colour roles of the path screen with T, G and K on match their approved letters", "[session][colour]")
{
    const GraphicsScreen screen = every_overlay();
    const CellGrid grid = render_cells(screen, {80, 24}, GlyphSet::braille);
    test::check_golden("path_colour_roles_braille.txt", grid.to_text() + "\n" + grid.roles_text());
}

TEST_CASE("NO_COLOR set and not empty, or --color never, draw in one colour — --color always outranks NO_COLOR",
          "[session][colour]")
{
    REQUIRE(session_colour(ColourChoice::automatic, nullptr) == ColourChoice::automatic);
    REQUIRE(session_colour(ColourChoice::automatic, "") == ColourChoice::automatic);
    REQUIRE(session_colour(ColourChoice::automatic, "1") == ColourChoice::never);
    REQUIRE(session_colour(ColourChoice::never, nullptr) == ColourChoice::never);
    REQUIRE(session_colour(ColourChoice::always, "1") == ColourChoice::always);
}

TEST_CASE("the path screen's help names each overlay's colour in that colour", "[session][colour]")
{
    const CellGrid help = key_help_screen("the staff", KeyContext::staff);
    const std::string text = help.to_text();
    for (const ColourRole role : colour_roles) {
        const std::string item = std::string(colour_role_name(role)) + " " + std::string(colour_name(role));
        CAPTURE(item);
        const std::size_t at = text.find(item);
        REQUIRE(at != std::string::npos);
        const int row = static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
        const std::size_t line_start = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
        REQUIRE(help.role_at(static_cast<int>(at - line_start), row) == role);
    }
    // Every legend row fits the 80 columns with a column to spare.
    for (int row = 0; row < help.rows(); ++row)
        REQUIRE(help.at(help.columns() - 1, row) == U' ');
    REQUIRE(key_help_screen("KEY1", KeyContext::text_line).to_text().find("Colours") == std::string::npos);
}
