// Compare (C, SPEC §3.1): the curve pinned as reference A, labelled with its staff values, drawn
// dashed in a colour role of its own beside the live curve until C unpins it.
#include "apcs/editor/path_editor.h"
#include "apcs/screens/reference_curve.h"
#include "apcs/screens/words.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <string_view>

using namespace apcs;
using apcs::test::apply;
using apcs::test::LogLines;
namespace cmd = apcs::command;

namespace {

// way1.dat's shape: the middle point is where continuity makes a corner or a spike.
PathEditor::Setup three_points()
{
    PathEditor::Setup setup = apcs::test::path_setup({Vec3{0, 0, 0}, Vec3{4, 3, 0}, Vec3{8, 0, 0}},
                                                     {{1, 1}, 8, 5, Spacing::nearest});
    setup.view_angles = {-90.0, 0.0};
    return setup;
}

// Global control, on the CONTINUITY line, moved `threes` times three steps (0.15 each).
void continuity_steps(PathEditor& editor, int threes)
{
    for (int k = 0; k < std::abs(threes); ++k)
        apply(editor, {cmd::StaffStep{threes < 0 ? -3 : +3}});
}

// Cells of the drawing (inside the boundary's frame) in `role`.
std::size_t drawing_cells(const CellGrid& grid, ColourRole role)
{
    std::size_t cells = 0;
    for (int row = 1; row < 17; ++row)
        for (int column = 1; column < 79; ++column)
            cells += grid.role_at(column, row) == role && grid.at(column, row) != U' ' && grid.at(column, row) != U'\u2800';
    return cells;
}

// Whether the top edge holds the label " A: continuity -1.00 " from column 2, in the reference's role.
bool labelled_on_top_edge(const CellGrid& grid)
{
    const std::string_view label = " A: continuity -1.00 ";
    for (std::size_t k = 0; k < label.size(); ++k) {
        const int column = 2 + static_cast<int>(k);
        if (grid.at(column, 0) != static_cast<char32_t>(label[k]) || grid.role_at(column, 0) != ColourRole::reference)
            return false;
    }
    return true;
}

bool any_label(const CellGrid& grid)
{
    for (int column = 0; column + 1 < grid.columns(); ++column)
        if (grid.at(column, 0) == U'A' && grid.at(column + 1, 0) == U':')
            return true;
    return false;
}

bool letter_in_drawing(const CellGrid& grid)
{
    for (int row = 1; row < 17; ++row)
        for (int column = 1; column < 79; ++column)
            if (grid.at(column, row) == U'A' && grid.role_at(column, row) == ColourRole::reference)
                return true;
    return false;
}

} // namespace

TEST_CASE("the reference's label names the staff values that are not 0", "[editor][compare]")
{
    CHECK(reference_label({0.0, -1.0, 0.0, 0.0}) == "A: continuity -1.00");
    CHECK(reference_label({0.5, 0.0, -0.25, 0.0}) == "A: tension +0.50  bias -0.25");
    CHECK(reference_label({}) == "A: tension, continuity, bias 0");
    // Four values in full would crowd a replay's badge on the top edge: their initials then.
    CHECK(reference_label({0.5, -1.0, 0.25, -0.3}) == "A: t +0.50  c -1.00  b +0.25  a -0.30");
}

TEST_CASE("C pins the curve as reference A beside the live curve until C unpins it", "[editor][compare]")
{
    LogLines log;
    PathEditor editor(three_points(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}});
    continuity_steps(editor, -7); // -1.05, held at -1
    const std::uint64_t before_pin = editor.revision();
    apply(editor, {cmd::PinReference{}});
    CHECK(editor.revision() > before_pin);
    CHECK(editor.message_line() == "A: continuity -1.00 pinned, dashed: under the curve till it moves (C unpins)");
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille}) {
        CAPTURE(glyphs);
        const CellGrid pinned = render_cells(editor.view(), {80, 24}, glyphs);
        // Just pinned, the reference is the curve: the curve stands over it, so only its label shows.
        CHECK(labelled_on_top_edge(pinned));
        CHECK(drawing_cells(pinned, ColourRole::reference) == 0);
        CHECK_FALSE(letter_in_drawing(pinned));
    }
    // A key that leaves the curve as it is: the message line still says why A cannot be seen.
    apply(editor, {cmd::ToggleLawGraph{}, cmd::ToggleLawGraph{}});
    CHECK(editor.message_line() == words::reference_under_curve);
    continuity_steps(editor, +14); // +1
    CHECK(editor.message_line() != words::reference_under_curve);
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille, GlyphSet::blocks}) {
        CAPTURE(glyphs);
        const CellGrid compared = render_cells(editor.view(), {80, 24}, glyphs);
        // The corner at -1 beside the spike at +1: a class sees two curves, the pinned one lettered.
        CHECK(drawing_cells(compared, ColourRole::reference) >= 12);
        CHECK(letter_in_drawing(compared));
        CHECK(labelled_on_top_edge(compared));
        // The ghost (the curve one key back) steps aside while a reference is pinned.
        CHECK(drawing_cells(compared, ColourRole::ghost) == 0);
    }
    apply(editor, {cmd::PinReference{}});
    CHECK(editor.message_line() == "reference A unpinned (C pins the curve as it is)");
    const CellGrid unpinned = render_cells(editor.view(), {80, 24}, GlyphSet::braille);
    CHECK(drawing_cells(unpinned, ColourRole::reference) == 0);
    CHECK_FALSE(letter_in_drawing(unpinned));
    CHECK_FALSE(any_label(unpinned));
    CHECK(drawing_cells(unpinned, ColourRole::ghost) > 0);
}

TEST_CASE("the reference is drawn again in every view the path screen takes", "[editor][compare]")
{
    LogLines log;
    PathEditor editor(three_points(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}});
    continuity_steps(editor, -7);
    apply(editor, {cmd::PinReference{}});
    // Zoomed (and back), the unchanged curve still covers its reference: pixels kept from the
    // view before would stand apart from it.
    for (int zoom = 1; zoom <= 4; ++zoom) {
        apply(editor, {cmd::Zoom{}});
        CAPTURE(zoom);
        const CellGrid grid = render_cells(editor.view(), {80, 24}, GlyphSet::braille);
        CHECK(drawing_cells(grid, ColourRole::reference) == 0);
        CHECK(labelled_on_top_edge(grid));
    }
}

TEST_CASE("the reference outlives the region and the staff it was pinned on", "[editor][compare]")
{
    LogLines log;
    PathEditor editor(three_points(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}});
    continuity_steps(editor, -7);
    apply(editor, {cmd::PinReference{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}});
    // "Adjust the path again ?": Y, then global control again, continuity back to 0.
    REQUIRE(editor.update(cmd::Yes{}) == PathEditor::Outcome::editing);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}});
    continuity_steps(editor, +7);
    const CellGrid grid = render_cells(editor.view(), {80, 24}, GlyphSet::braille);
    CHECK(drawing_cells(grid, ColourRole::reference) >= 12);
    CHECK(labelled_on_top_edge(grid));
}

TEST_CASE("the pin's notice fits the message line, whatever the label", "[editor][compare]")
{
    LogLines log;
    PathEditor editor(three_points(), log);
    // Tension, continuity, bias and acceleration each moved: the label names all four.
    apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{+3}, cmd::Accept{}, cmd::StaffStep{-3}, cmd::Accept{},
                   cmd::StaffStep{+3}, cmd::Accept{}, cmd::StaffStep{-3}, cmd::PinReference{}});
    const std::string message = editor.message_line();
    CAPTURE(message);
    CHECK(message.starts_with("A: t +0.15  c -0.15  b +0.15  a -0.15"));
    CHECK(message.ends_with(" pinned, dashed (C unpins)"));
    CHECK(message.size() < 80);
}

TEST_CASE("a pinned A stays under the curve through an acceleration step, and T's numbers say so after them",
          "[editor][compare]")
{
    LogLines log;
    PathEditor editor(three_points(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::StaffStep{-3}, cmd::PinReference{}});
    // Down to ACCELERATION and a step there: the in-betweens move, the curve does not.
    apply(editor, {cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{+3}});
    CHECK(editor.message_line() == words::reference_under_curve);
    apply(editor, {cmd::ToggleTangents{}});
    CHECK(editor.message_line().starts_with("point 2  DS "));
    CHECK(editor.message_line().ends_with("  (A under the curve)"));
    apply(editor, {cmd::ChoosePoint{+1}});
    CHECK(editor.message_line().starts_with("point 3  DS "));
}
