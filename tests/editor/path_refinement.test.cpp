// A first picture refined after (Refinement::in_steps, the terminal's): the work a change leaves —
// exact spacing's arc lengths and the in-betweens on them, the curve's blocks past a step's work —
// done in steps, changes made meanwhile added to it, comes out as the work done at once: the numbers
// to the bit, the screen to the pixel.
#include "apcs/screens/curve_raster.h"
#include "apcs/editor/path_editor.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/words.h"

#include "support/same_path.h"
#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

using namespace apcs;
using apcs::test::apply;
using apcs::test::LogLines;
using apcs::test::message_of;
using apcs::test::require_same_path;
namespace cmd = apcs::command;

namespace {

// Control points zigzagging over the screen: most samples on pixels of their own, every block of
// the curve drawn at some cost.
ControlPoints zigzag(int count)
{
    ControlPoints points;
    for (int k = 0; k < count; ++k)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.001, std::cos(k * 0.37) * 2.0}, {}});
    return points;
}

// Steps of `most` segments until refined; returns how many it took.
int refine_in_steps(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                    std::size_t most)
{
    int steps = 1;
    for (; !refine_path(points, settings, path, most); ++steps)
        REQUIRE(steps < 100000);
    return steps;
}

} // namespace

TEST_CASE("exact spacing's arc lengths, marked by changes one over another and measured in small steps, are "
          "those measured afresh",
          "[animation][refinement]")
{
    ControlPoints points = zigzag(3000);
    const PathSettings settings{{1, 1}, 8, 12, Spacing::exact};
    EvaluatedPath path;
    evaluate_path(points, settings, path, Refinement::in_steps);
    REQUIRE_FALSE(path.inbetweens_current);
    REQUIRE(path.arc_lengths.pending());
    REQUIRE(refine_in_steps(points, settings, path, 700) == 5);
    require_same_path(path, evaluate_path(points, settings));

    const auto change = [&](const PathChange& what) { reevaluate_path(points, settings, path, what, Refinement::in_steps); };
    // A global key, a third of it measured, then a local key, an insertion, a deletion and an
    // acceleration, each over what the one before left.
    for (ControlPoint& point : points)
        point.staff.tension = 0.4;
    change({0, points.size(), points.size(), PathChange::What::staff});
    REQUIRE_FALSE(refine_path(points, settings, path, 1000));
    for (std::size_t k = 2000; k < 2010; ++k)
        points[k].staff.bias = -0.3;
    change({2000, 10, 10, PathChange::What::staff});
    points.insert(points.begin() + 1500, ControlPoint{{1.0, 1.5, -1.0}, {}});
    change({1500, 0, 1, PathChange::What::positions});
    REQUIRE_FALSE(refine_path(points, settings, path, 10));
    points.erase(points.begin() + 2999);
    change({2999, 1, 0, PathChange::What::positions});
    for (std::size_t k = 100; k < 200; ++k)
        points[k].staff.acceleration = 0.5;
    change({100, 100, 100, PathChange::What::accelerations});
    REQUIRE_FALSE(path.inbetweens_current);
    refine_in_steps(points, settings, path, 333);
    require_same_path(path, evaluate_path(points, settings));

    SECTION("a change made at once over what steps left measures that too")
    {
        for (ControlPoint& point : points)
            point.staff.continuity = -0.2;
        change({0, points.size(), points.size(), PathChange::What::staff});
        REQUIRE_FALSE(refine_path(points, settings, path, 100));
        points[5].staff.tension = 0.9;
        reevaluate_path(points, settings, path, PathChange{5, 1, 1, PathChange::What::staff});
        require_same_path(path, evaluate_path(points, settings));
    }
    SECTION("nearest spacing: a change of values waits for its segments, made in steps in path order; a change "
            "that inserts a point makes them at once")
    {
        const PathSettings nearest{{1, 1}, 8, 12, Spacing::nearest};
        EvaluatedPath near = evaluate_path(points, nearest);
        const HermiteSegments before = near.curve.segments;
        const auto change_near = [&](const PathChange& what) {
            reevaluate_path(points, nearest, near, what, Refinement::in_steps);
        };
        for (ControlPoint& point : points)
            point.staff.continuity = 0.3;
        change_near({0, points.size(), points.size(), PathChange::What::staff});
        // Not one segment made: the key's first picture waits for none.
        REQUIRE_FALSE(near.inbetweens_current);
        REQUIRE(near.segments_unmade == SegmentRange{0, points.size() - 1});
        REQUIRE(near.curve.segments == before);
        REQUIRE_FALSE(refine_path(points, nearest, near, 1000));
        REQUIRE(near.segments_unmade == SegmentRange{1000, points.size() - 1});
        const EvaluatedPath fresh = evaluate_path(points, nearest);
        REQUIRE(std::equal(fresh.curve.segments.begin(), fresh.curve.segments.begin() + 1000, near.curve.segments.begin()));
        REQUIRE(near.curve.segments[1000] == before[1000]);
        // A local key before them joins what is left.
        points[7].staff.tension = -0.5;
        change_near({7, 1, 1, PathChange::What::staff});
        REQUIRE(near.segments_unmade == SegmentRange{5, points.size() - 1});
        REQUIRE_FALSE(refine_path(points, nearest, near, 2000));
        // A point inserted: every segment left is made, only the in-betweens wait.
        points.insert(points.begin() + 1500, ControlPoint{{1.0, 1.5, -1.0}, {}});
        change_near({1500, 0, 1, PathChange::What::positions});
        REQUIRE(near.segments_unmade.empty());
        REQUIRE_FALSE(near.inbetweens_current);
        REQUIRE(refine_in_steps(points, nearest, near, 500) == 1);
        require_same_path(near, evaluate_path(points, nearest));
        // An acceleration and a point moved while segments wait: the in-betweens wait, the move
        // joins what is left.
        for (ControlPoint& point : points)
            point.staff.tension = 0.1;
        change_near({0, points.size(), points.size(), PathChange::What::staff});
        REQUIRE_FALSE(refine_path(points, nearest, near, 1200));
        points[30].staff.acceleration = -0.4;
        change_near({30, 1, 1, PathChange::What::accelerations});
        REQUIRE(near.segments_unmade == SegmentRange{1200, points.size() - 1});
        REQUIRE_FALSE(near.inbetweens_current);
        points[600].position.x += 0.25;
        change_near({600, 1, 1, PathChange::What::positions});
        REQUIRE(near.segments_unmade == SegmentRange{598, points.size() - 1});
        refine_in_steps(points, nearest, near, 400);
        require_same_path(near, evaluate_path(points, nearest));
        // A global key left in steps, then a local key and an acceleration made at once.
        for (ControlPoint& point : points)
            point.staff.bias = -0.1;
        change_near({0, points.size(), points.size(), PathChange::What::staff});
        REQUIRE_FALSE(refine_path(points, nearest, near, 700));
        points[2500].staff.tension = 0.2;
        reevaluate_path(points, nearest, near, PathChange{2500, 1, 1, PathChange::What::staff});
        require_same_path(near, evaluate_path(points, nearest));
        change_near({0, points.size(), points.size(), PathChange::What::staff});
        points[40].staff.acceleration = 0.6;
        reevaluate_path(points, nearest, near, PathChange{40, 1, 1, PathChange::What::accelerations});
        require_same_path(near, evaluate_path(points, nearest));
    }
}

namespace {

PathEditor::Setup zigzag_setup(Spacing spacing, Refinement when)
{
    PathEditor::Setup setup;
    setup.path_name = "way1.dat";
    // 13000: a global key leaves the curve some 50 blocks of 256 segments, more than the first
    // round draws.
    setup.points = zigzag(13000);
    setup.settings = {{1, 1}, 8, 12, spacing};
    // Small steps, so that a path of 13000 points takes many (the terminal's are 2^15 arc lengths,
    // 2^17 segments made).
    setup.refinement = {when, 900, 20000, 1000};
    return setup;
}

std::vector<std::tuple<int, int, MarkKind, CellStyle>> marks_of(const GraphicsScreen& screen)
{
    std::vector<std::tuple<int, int, MarkKind, CellStyle>> marks;
    for (const PixelMark& mark : screen.marks)
        marks.emplace_back(mark.at.x, mark.at.y, mark.kind, mark.style);
    return marks;
}

bool has_inbetween_marks(const GraphicsScreen& screen)
{
    for (const PixelMark& mark : screen.marks)
        if (mark.kind == MarkKind::inbetween)
            return true;
    return false;
}

// The editor whose pictures were refined in steps shows what the one that made each at once shows,
// to the pixel and the message, and holds the same path.
void require_same_screen(const PathEditor& in_steps, const PathEditor& at_once)
{
    const GraphicsScreen expected = at_once.view();
    const GraphicsScreen shown = in_steps.view();
    REQUIRE(shown.bitmap == expected.bitmap);
    REQUIRE(marks_of(shown) == marks_of(expected));
    REQUIRE(message_of(shown) == message_of(expected));
    require_same_path(in_steps.evaluated(), at_once.evaluated());
}

// Refines in steps, each first picture saying that it is one; returns the steps taken.
int refine_editor(PathEditor& editor)
{
    int steps = 0;
    while (editor.refining()) {
        const GraphicsScreen first = editor.view();
        const std::string message = message_of(first);
        // The 8/2 question stays, what is left following it in a few words.
        const std::string question(words::choose_control);
        const bool says_so = message.starts_with("drawing the curve: ") || message.starts_with("measuring arc lengths") ||
                             message == question + "    (drawing the curve...)" ||
                             message == question + "    (measuring arc lengths...)";
        REQUIRE(says_so);
        if (message.find("measuring") != std::string::npos)
            REQUIRE_FALSE(has_inbetween_marks(first));
        editor.refine_step();
        REQUIRE(++steps < 10000);
    }
    return steps;
}

// The same path in two editors, one making every key's picture at once, the other in steps.
struct TwinEditors {
    explicit TwinEditors(Spacing spacing)
        : at_once(zigzag_setup(spacing, Refinement::at_once), log)
        , in_steps(zigzag_setup(spacing, Refinement::in_steps), log)
    {
    }
    void both(std::initializer_list<Command> commands)
    {
        apply(at_once, commands);
        apply(in_steps, commands);
    }

    LogLines log;
    PathEditor at_once;
    PathEditor in_steps;
};

} // namespace

TEST_CASE("every key's picture, refined in steps before the next, is the picture made at once, ghost and message "
          "line included",
          "[session][editor][refinement]")
{
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        CAPTURE(static_cast<int>(spacing));
        TwinEditors twins(spacing);
        PathEditor& at_once = twins.at_once;
        PathEditor& in_steps = twins.in_steps;
        int steps_taken = refine_editor(in_steps);
        const auto same_screen = [&](const char* after) {
            CAPTURE(after);
            steps_taken += refine_editor(in_steps);
            require_same_screen(in_steps, at_once);
        };
        const auto both = [&](std::initializer_list<Command> commands) { twins.both(commands); };
        same_screen("opening");
        both({cmd::ChooseGlobal{}, cmd::StaffStep{+3}});
        same_screen("a global key on TENSION");
        both({cmd::StaffStep{-1}});
        same_screen("another, with the ghost of the first");
        both({cmd::Undo{}});
        same_screen("its undo");
        both({cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{-2}});
        same_screen("a global key on ACCELERATION");
        both({cmd::Accept{}, cmd::Yes{}, cmd::ChooseLocal{}, cmd::ArrowMove{1}, cmd::ArrowMove{4094}, cmd::Accept{},
              cmd::ArrowMove{3}, cmd::Accept{}, cmd::StaffStep{-4}});
        same_screen("a local key across two blocks");
        both({cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Yes{}, cmd::OpenWaypoints{},
              cmd::ChoosePoint{4095}, cmd::MovePoint{2, -1, 1}, cmd::InsertPoint{}, cmd::ChoosePoint{-3},
              cmd::DeletePoint{}});
        same_screen("waypoints moved, inserted and deleted");
        both({cmd::Undo{}, cmd::Accept{}, cmd::Undo{}});
        same_screen("waypoint changes undone");
        // The steps were taken: the first pictures were first pictures (the curve's last block at
        // opening and after each global key; 15 steps of arc lengths too for each with exact spacing).
        REQUIRE(steps_taken >= (spacing == Spacing::exact ? 40 : 4));
    }
}

TEST_CASE("an opened path's 8/2 question stands on its first picture, and 8 or 2 opens the staff or the pick while "
          "the arc lengths are measured",
          "[session][editor][refinement]")
{
    LogLines log;
    const std::string question(words::choose_control);
    for (const bool global : {true, false}) {
        CAPTURE(global);
        PathEditor editor(zigzag_setup(Spacing::exact, Refinement::in_steps), log);
        REQUIRE(editor.refining());
        REQUIRE(message_of(editor.view()) == question + "    (drawing the curve...)");
        while (message_of(editor.view()).find("drawing") != std::string::npos)
            editor.refine_step();
        REQUIRE(editor.refining());
        REQUIRE(message_of(editor.view()) == question + "    (measuring arc lengths...)");
        REQUIRE_FALSE(has_inbetween_marks(editor.view()));
        const Command choice = global ? Command{cmd::ChooseGlobal{}} : Command{cmd::ChooseLocal{}};
        apply(editor, {choice});
        REQUIRE(editor.leaf() == (global ? PathEditor::State::staff : PathEditor::State::region_first));
        REQUIRE(editor.refining());
        REQUIRE(message_of(editor.view()).starts_with("measuring arc lengths for exact spacing"));
        refine_editor(editor);
        PathEditor at_once(zigzag_setup(Spacing::exact, Refinement::at_once), log);
        apply(at_once, {choice});
        require_same_screen(editor, at_once);
    }
}

TEST_CASE("keys pressed before the picture is refined are added to what is left — refined, the path and its "
          "screen are those evaluated and drawn afresh",
          "[session][editor][refinement]")
{
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        CAPTURE(static_cast<int>(spacing));
        LogLines log;
        PathEditor editor(zigzag_setup(spacing, Refinement::in_steps), log);
        const PathSettings settings = zigzag_setup(spacing, Refinement::at_once).settings;
        apply(editor, {cmd::ToggleGhost{}}); // a fresh draw has no ghost; O finished the opening's steps
        REQUIRE_FALSE(editor.refining());
        const auto matches_fresh = [&](const char* after) {
            CAPTURE(after);
            refine_editor(editor);
            require_same_path(editor.evaluated(), evaluate_path(editor.points(), settings));
            const EvaluatedPath fresh = evaluate_path(editor.points(), settings);
            PathScreenContent content = path_screen_content(editor.points(), fresh);
            const GraphicsScreen drawn = draw_path_screen(content, editor.view_transform());
            const GraphicsScreen shown = editor.view();
            REQUIRE(shown.bitmap == drawn.bitmap);
            const auto inbetweens = [](const GraphicsScreen& screen) {
                std::vector<std::tuple<int, int>> at;
                for (const PixelMark& mark : screen.marks)
                    if (mark.kind == MarkKind::inbetween)
                        at.emplace_back(mark.at.x, mark.at.y);
                return at;
            };
            REQUIRE(inbetweens(shown) == inbetweens(drawn));
        };
        apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{+3}});
        REQUIRE(editor.refining());
        editor.refine_step();
        apply(editor, {cmd::StaffStep{+2}});
        editor.refine_step();
        editor.refine_step();
        apply(editor, {cmd::StaffStep{-7}});
        REQUIRE(editor.refining());
        matches_fresh("three global keys, each before the last was refined");
        apply(editor, {cmd::StaffStep{+1}});
        editor.refine_step();
        // Undo is no staff step: it finishes what is left first, then is refined itself.
        apply(editor, {cmd::Undo{}});
        matches_fresh("an undo pressed mid-refinement");
        apply(editor, {cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{+4}, cmd::StaffStep{-1}});
        matches_fresh("two ACCELERATION keys");
        apply(editor, {cmd::Accept{}, cmd::Yes{}, cmd::OpenWaypoints{}, cmd::ChoosePoint{5000}, cmd::MovePoint{1, 1, 0},
                       cmd::InsertPoint{}, cmd::InsertPoint{}, cmd::ChoosePoint{-4000}, cmd::DeletePoint{}});
        matches_fresh("waypoint edits one over another");
        apply(editor, {cmd::Accept{}, cmd::ChooseGlobal{}, cmd::StaffStep{-3}, cmd::StaffStep{-3}});
        REQUIRE(editor.refining());
        apply(editor, {cmd::Accept{}});
        // Enter finished the refinement before it took the line.
        REQUIRE_FALSE(editor.refining());
        matches_fresh("Enter after two keys");
    }
}

TEST_CASE("keys pressed while the curve is still drawn keep the ghost drawn whole — Z draws it again from the path "
          "two changes back",
          "[session][editor][refinement][view]")
{
    LogLines log;
    const PathEditor::Setup setup = zigzag_setup(Spacing::nearest, Refinement::in_steps);
    const ControlPoints opened = setup.points;
    PathEditor editor(setup, log);
    refine_editor(editor);
    apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{+3}});
    REQUIRE(message_of(editor.view()).rfind("drawing the curve", 0) == 0);
    apply(editor, {cmd::StaffStep{+3}});
    apply(editor, {cmd::Zoom{}});
    refine_editor(editor); // the zoomed view's curve is drawn in steps too
    // The ghost: what O takes away.
    const Bitmap with_ghost = editor.view().bitmap;
    apply(editor, {cmd::ToggleGhost{}});
    const Bitmap without_ghost = editor.view().bitmap;
    CurveRaster opened_curve;
    opened_curve.update(evaluate_path(opened, setup.settings).curve, editor.view_transform(), layout::inside_boundary);
    std::size_t ghost = 0;
    std::size_t on_opened_curve = 0;
    for (int y = 0; y < with_ghost.height(); ++y)
        for (int x = 0; x < with_ghost.width(); ++x)
            if (with_ghost.get(x, y) && !without_ghost.get(x, y)) {
                ++ghost;
                if (opened_curve.pixels().get(x, y))
                    ++on_opened_curve;
            }
    REQUIRE(ghost > 50);
    REQUIRE(on_opened_curve == ghost);
}

TEST_CASE("a staff key pressed before the last one's picture is refined says, once refined, how far it moved the "
          "curve, as the key made at once says",
          "[session][editor][refinement]")
{
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        CAPTURE(static_cast<int>(spacing));
        TwinEditors twins(spacing);
        refine_editor(twins.in_steps);
        const auto tangent_ends = [](const GraphicsScreen& screen) {
            return std::ranges::count_if(screen.marks,
                                         [](const PixelMark& mark) { return mark.kind == MarkKind::tangent_end; });
        };
        twins.both({cmd::ToggleTangents{}});
        REQUIRE(tangent_ends(twins.in_steps.view()) > 0);
        twins.both({cmd::ChooseGlobal{}, cmd::StaffStep{+3}});
        // The global key made no segment yet: its first picture waits for none, and draws no
        // tangent of an earlier state.
        REQUIRE(twins.in_steps.evaluated().segments_unmade.size() == twins.in_steps.points().size() - 1);
        REQUIRE(tangent_ends(twins.in_steps.view()) == 0);
        twins.in_steps.refine_step();
        twins.both({cmd::StaffStep{+2}});
        const std::string meanwhile = message_of(twins.in_steps.view());
        CAPTURE(meanwhile);
        // 12999 segments made again by the global key: 49 blocks of 256 (CurveRaster::block_segments)
        // and the last of 455.
        REQUIRE(CurveRaster::block_segments(12999) == 256);
        REQUIRE(meanwhile.starts_with("drawing the curve: 0 of 50 blocks"));
        refine_editor(twins.in_steps);
        const std::string said = message_of(twins.at_once.view());
        REQUIRE(said.find("moved up to") != std::string::npos);
        REQUIRE(message_of(twins.in_steps.view()) == said);
        REQUIRE(twins.in_steps.view().marks.size() == twins.at_once.view().marks.size());
    }
}
