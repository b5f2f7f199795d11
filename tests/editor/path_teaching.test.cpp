// Issue 13 on the path screen: tangents (T), the law graph (G), typed values (=), a region of one
// control point and undo (U), each against values worked by hand from the formulas.
#include "apcs/animation/speed_law.h"
#include "apcs/editor/path_editor.h"
#include "apcs/screens/path_overlays.h"

#include "support/golden.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace apcs;
using apcs::test::apply;
using apcs::test::LogLines;
using apcs::test::message_of;
namespace cmd = apcs::command;

namespace {

// A zigzag in the x-y plane: chords (2,0,0), (0,2,0), (2,0,0).
PathEditor::Setup zigzag()
{
    PathEditor::Setup setup = apcs::test::path_setup({Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{2, 2, 0}, Vec3{4, 2, 0}},
                                                     {{1, 1}, 16, 5, Spacing::exact});
    setup.view_angles = {-90.0, 0.0}; // top: x right, y up
    return setup;
}

void type(PathEditor& editor, const std::string& text)
{
    for (const char character : text)
        apply(editor, {cmd::TypeCharacter{static_cast<char32_t>(character)}});
}

std::string staff_line_label(const GraphicsScreen& screen)
{
    for (const TextLine& line : screen.text)
        if (line.row >= 19 && line.row <= 22 && line.text.starts_with(">"))
            return line.text.substr(1);
    return {};
}

} // namespace

TEST_CASE("T shows the KB tangents of Eq. 3.1.4 at the chosen control point — Tab moves the choice", "[session][teaching]")
{
    LogLines log;
    PathEditor editor(zigzag(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::ToggleTangents{}});
    // t = c = b = 0 at P1: DS = DD = ((P1 - P0) + (P2 - P1)) / 2 = (1, 1, 0).
    REQUIRE(message_of(editor.view()) == "point 2  DS 1.00 1.00 0.00  DD 1.00 1.00 0.00");
    apply(editor, {cmd::Accept{}, cmd::OpenValueField{}});
    type(editor, "0.5");
    apply(editor, {cmd::SubmitLine{}});
    // c = 0.5: DS = [0.5·(2,0,0) + 1.5·(0,2,0)] / 2, DD = [1.5·(2,0,0) + 0.5·(0,2,0)] / 2.
    REQUIRE(message_of(editor.view()) == "point 2  DS 0.50 1.50 0.00  DD 1.50 0.50 0.00  moved up to 0.08 = 8 px");
    apply(editor, {cmd::ChoosePoint{+1}});
    REQUIRE(message_of(editor.view()) == "point 3  DS 1.50 0.50 0.00  DD 0.50 1.50 0.00");
    apply(editor, {cmd::ChoosePoint{+1}});
    // The last point's DS is the end slope (1) times its chord.
    REQUIRE(message_of(editor.view()) == "point 4  DS 2.00 0.00 0.00  no DD (last point)");
    apply(editor, {cmd::ChoosePoint{+1}});
    REQUIRE(message_of(editor.view()) == "point 1  no DS (first point)  DD 2.00 0.00 0.00");
    apply(editor, {cmd::ChoosePoint{-1}, cmd::ChoosePoint{-1}});
    REQUIRE(message_of(editor.view()) == "point 3  DS 1.50 0.50 0.00  DD 0.50 1.50 0.00");
}

TEST_CASE("tension 1 shrinks both tangents to 0 and their arrows vanish", "[session][teaching]")
{
    LogLines log;
    PathEditor editor(zigzag(), log);
    apply(editor, {cmd::ChooseGlobal{}});
    const std::size_t lit_without = editor.view().bitmap.lit_count();
    apply(editor, {cmd::ToggleTangents{}});
    const std::size_t lit_with = editor.view().bitmap.lit_count();
    REQUIRE(lit_with > lit_without + 40);
    apply(editor, {cmd::OpenValueField{}});
    type(editor, "1");
    apply(editor, {cmd::SubmitLine{}});
    REQUIRE(message_of(editor.view()) == "point 2  DS 0.00 0.00 0.00  DD 0.00 0.00 0.00  moved up to 0.15 = 15 px");
    // Only the end arrows (slopes, not tension) are left: fewer lit pixels than with t = 0.
    apply(editor, {cmd::ToggleTangents{}});
    const std::size_t lit_tense_without = editor.view().bitmap.lit_count();
    apply(editor, {cmd::ToggleTangents{}});
    REQUIRE(editor.view().bitmap.lit_count() - lit_tense_without < lit_with - lit_without);
}

TEST_CASE("the law graph's ticks are the in-betweens' distances within their span", "[session][teaching]")
{
    ControlPoints points = zigzag().points;
    for (ControlPoint& point : points)
        point.staff.acceleration = 0.5;
    SECTION("exact spacing: on the law's curve, frame j of M at j / (M + 1)")
    {
        const EvaluatedPath path = evaluate_path(points, {{1, 1}, 16, 5, Spacing::exact});
        const std::vector<LawTick> ticks = law_ticks(path, 0);
        REQUIRE(ticks.size() == 5);
        for (std::size_t j = 0; j < ticks.size(); ++j) {
            const double tau = static_cast<double>(j + 1) / 6.0;
            REQUIRE(ticks[j].frame_fraction == Approx(tau));
            REQUIRE(ticks[j].distance_fraction == Approx(acceleration_distance_fraction(tau, 0.5)).margin(1e-9));
        }
    }
    SECTION("two spans: each span's own in-betweens, measured from its start")
    {
        points[2].staff.acceleration = -1.0;
        const EvaluatedPath path = evaluate_path(points, {{1, 1}, 16, 7, Spacing::exact});
        REQUIRE(path.span_timings.size() == 2);
        REQUIRE(span_of_point(path, 1) == 0u);
        REQUIRE(span_of_point(path, 2) == 1u);
        REQUIRE(span_of_point(path, 3) == 1u);
        const SpanTiming& second = path.span_timings[1];
        const std::vector<LawTick> ticks = law_ticks(path, 1);
        REQUIRE(ticks.size() == second.inbetween_count);
        REQUIRE(path.span_timings[0].inbetween_count + second.inbetween_count == 7);
        for (std::size_t j = 0; j < ticks.size(); ++j) {
            const double tau = static_cast<double>(j + 1) / static_cast<double>(ticks.size() + 1);
            REQUIRE(ticks[j].distance_fraction == Approx(acceleration_distance_fraction(tau, -1.0)).margin(1e-9));
        }
    }
    SECTION("the thesis' nearest samples: each tick is its in-between's chord distance")
    {
        const EvaluatedPath path = evaluate_path(points, {{1, 1}, 4, 5, Spacing::nearest});
        const std::vector<LawTick> ticks = law_ticks(path, 0);
        for (std::size_t j = 0; j < ticks.size(); ++j)
            REQUIRE(ticks[j].distance_fraction ==
                    Approx(path.curve.chord_length(path.inbetweens[j].sample_index) / path.curve.total_length()));
    }
}

TEST_CASE("G draws the law of the region's span in an inset, titled with its acceleration", "[session][teaching]")
{
    LogLines log;
    PathEditor editor(zigzag(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{+3},
                   cmd::StaffStep{+3}, cmd::ToggleLawGraph{}});
    const GraphicsScreen screen = editor.view();
    const auto titled = [](const GraphicsScreen& shown) {
        return std::count_if(shown.text.begin(), shown.text.end(),
                             [](const TextLine& line) { return line.text == "law a +0.30"; });
    };
    REQUIRE(titled(screen) == 1);
    apply(editor, {cmd::ToggleLawGraph{}});
    REQUIRE(titled(editor.view()) == 0);
}

TEST_CASE("the law inset takes the corner that hides the fewest control points and shows M ticks", "[session][teaching]")
{
    ControlPoints points = zigzag().points;
    const EvaluatedPath path = evaluate_path(points, {{1, 1}, 16, 5, Spacing::exact});
    const std::vector<PixelRect> corners = law_inset_corners();
    REQUIRE(corners.size() == 4);
    GraphicsScreen screen;
    // A control point in the top-right corner, in-betweens in the top-left: the bottom-right is free.
    const auto centre = [](const PixelRect& box) { return PixelPoint{(box.left + box.right) / 2, (box.top + box.bottom) / 2}; };
    screen.marks.push_back({centre(corners[0]), MarkKind::control_point});
    screen.marks.push_back({centre(corners[1]), MarkKind::inbetween});
    const PixelRect box = draw_law_inset(screen, path, 0);
    REQUIRE(box.left == corners[2].left);
    REQUIRE(box.top == corners[2].top);
    const auto ticks = std::count_if(screen.marks.begin(), screen.marks.end(),
                                     [&](const PixelMark& mark) { return box.contains(mark.at); });
    REQUIRE(ticks == 5);
    REQUIRE(screen.marks.size() == 7);
}

TEST_CASE("a staff value typed with a decimal comma is refused with its point shown", "[session][teaching]")
{
    LogLines log;
    PathEditor editor(zigzag(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::OpenValueField{}});
    type(editor, "-0,5");
    apply(editor, {cmd::SubmitLine{}});
    REQUIRE(message_of(editor.view()) == "'-0,5' is not a number: the decimal point is '.', type -0.5");
    type(editor, "=-0.5");
    apply(editor, {cmd::SubmitLine{}});
    REQUIRE(editor.key_context() == KeyContext::staff);
    REQUIRE(editor.points()[1].staff.tension == -0.5);
}

TEST_CASE("= types a staff value: clamped to -1 and +1, a non-number is refused and the field stays", "[session][teaching]")
{
    LogLines log;
    PathEditor editor(zigzag(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::OpenValueField{}});
    REQUIRE(editor.key_context() == KeyContext::value_field);
    REQUIRE(command_for(KeyContext::value_field, KeyEvent::typed(U'4')) == Command{cmd::TypeCharacter{U'4'}});
    REQUIRE(command_for(KeyContext::value_field, KeyEvent::typed(U'-')) == Command{cmd::TypeCharacter{U'-'}});
    REQUIRE(command_for(KeyContext::value_field, KeyEvent::typed(U'u')) == Command{cmd::TypeCharacter{U'u'}});
    type(editor, "abc");
    REQUIRE(message_of(editor.view()) == "TENSION = abc_  a value from -1 to 1, Enter sets it");
    apply(editor, {cmd::SubmitLine{}});
    REQUIRE(message_of(editor.view()) == "'abc' is not a number: type a value from -1 to 1, e.g. 0.35");
    REQUIRE(editor.key_context() == KeyContext::value_field);
    // The refused text is gone: a student who types '=' and the value again gets that value (it
    // was "'abc=0.35' is not a number", the open field hidden under the problem).
    type(editor, "=");
    REQUIRE(message_of(editor.view()) == "TENSION = _  a value from -1 to 1, Enter sets it");
    type(editor, "0.35");
    apply(editor, {cmd::SubmitLine{}});
    REQUIRE(editor.key_context() == KeyContext::staff);
    REQUIRE(staff_line_label(editor.view()) == "TENSION");
    REQUIRE(editor.points()[1].staff.tension == 0.35);
    apply(editor, {cmd::OpenValueField{}});
    type(editor, "-2");
    apply(editor, {cmd::SubmitLine{}});
    REQUIRE(message_of(editor.view()) == "TENSION set to -1.00: the staff runs from -1 to 1");
    REQUIRE(editor.points()[2].staff.tension == -1.0);
    // Esc closes the field and keeps the value; Enter then accepts the line as before.
    apply(editor, {cmd::OpenValueField{}});
    type(editor, "0.9");
    apply(editor, {cmd::ClearLine{}, cmd::Accept{}});
    REQUIRE(editor.points()[2].staff.tension == -1.0);
    REQUIRE(staff_line_label(editor.view()) == "CONTINUITY");
    REQUIRE(log.lines.back() == "TENSION -1.00");
}

TEST_CASE("Enter twice on one control point adjusts it alone and skips ACCELERATION", "[session][teaching]")
{
    LogLines log;
    PathEditor editor(zigzag(), log);
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::Accept{}, cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::staff);
    REQUIRE(log.lines.back() == "local control: control point 2");
    REQUIRE(message_of(editor.view()) == "way1.dat: TENSION  control point 2 of 4 (no span, no ACCELERATION)");
    apply(editor, {cmd::StaffStep{+3}, cmd::StaffStep{+3}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{-1}});
    REQUIRE(staff_line_label(editor.view()) == "BIAS");
    apply(editor, {cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::ask_again);
    for (std::size_t k = 0; k < 4; ++k) {
        const StaffValues expected = k == 1 ? StaffValues{0.3, 0.0, -0.05, 0.0} : StaffValues{};
        REQUIRE(editor.points()[k].staff == expected);
    }
    // The picked point before the first is still refused.
    apply(editor, {cmd::Yes{}, cmd::ChooseLocal{}, cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::Accept{},
                   cmd::ArrowMove{-1}, cmd::Accept{}});
    REQUIRE(message_of(editor.view()) == "The last control point must come after the first (point 2)");
}

TEST_CASE("U takes every change back, in reverse, to the staff line it was made on", "[session][teaching]")
{
    LogLines log;
    const PathEditor::Setup setup = zigzag();
    PathEditor editor(setup, log);
    apply(editor, {cmd::Undo{}});
    REQUIRE(message_of(editor.view()) == "Nothing to undo: the path is as it was opened");
    // Three changes: J/L is one, a typed value one, a step one; a step at the end of the line none.
    apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{+3}, cmd::Accept{}, cmd::OpenValueField{}});
    type(editor, "1");
    apply(editor, {cmd::SubmitLine{}, cmd::StaffStep{+1}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{+1},
                   cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::ask_again);
    apply(editor, {cmd::Undo{}});
    REQUIRE(editor.leaf() == PathEditor::State::staff);
    REQUIRE(staff_line_label(editor.view()) == "ACCELERATION");
    REQUIRE(message_of(editor.view()) == "Undone: ACCELERATION back to +0.00; 2 changes left to undo");
    apply(editor, {cmd::Undo{}});
    REQUIRE(staff_line_label(editor.view()) == "CONTINUITY");
    REQUIRE(editor.points()[1].staff.continuity == 0.0);
    REQUIRE(editor.points()[1].staff.tension == Approx(0.15));
    apply(editor, {cmd::Undo{}});
    REQUIRE(staff_line_label(editor.view()) == "TENSION");
    apply(editor, {cmd::Undo{}});
    REQUIRE(message_of(editor.view()) == "Nothing to undo: the path is as it was opened");
    for (std::size_t k = 0; k < setup.points.size(); ++k)
        REQUIRE(editor.points()[k].staff == setup.points[k].staff);
}

TEST_CASE("the teaching screens match their approved cells in each glyph set", "[session][teaching]")
{
    const auto check = [](const std::string& name, const GraphicsScreen& screen) {
        for (const auto& [glyphs, set] : {std::pair{GlyphSet::ascii, "ascii"}, std::pair{GlyphSet::braille, "braille"},
                                          std::pair{GlyphSet::blocks, "blocks"}})
            test::check_golden(name + "_" + set + ".txt", render_cells(screen, {80, 24}, glyphs).to_text());
    };
    LogLines log;
    SECTION("tangents and the law graph")
    {
        PathEditor editor(zigzag(), log);
        apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::StaffStep{+3}, cmd::ToggleTangents{},
                       cmd::ToggleLawGraph{}});
        check("path_teaching", editor.view());
    }
    SECTION("the value field")
    {
        PathEditor editor(zigzag(), log);
        apply(editor, {cmd::ChooseGlobal{}, cmd::OpenValueField{}});
        type(editor, "-0.35");
        check("path_value_field", editor.view());
    }
    SECTION("the waypoint editor, a point inserted and moved")
    {
        PathEditor editor(zigzag(), log);
        apply(editor, {cmd::OpenWaypoints{}, cmd::ChoosePoint{+1}, cmd::InsertPoint{}, cmd::MovePoint{0, 1, 0},
                       cmd::MovePoint{0, 1, 0}, cmd::MovePoint{+3, 0, 0}});
        REQUIRE(editor.leaf() == PathEditor::State::waypoints);
        check("path_waypoints", editor.view());
    }
    SECTION("a region of one control point")
    {
        PathEditor editor(zigzag(), log);
        apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::Accept{},
                       cmd::Accept{}, cmd::StaffStep{-3}});
        check("path_one_point", editor.view());
    }
}
