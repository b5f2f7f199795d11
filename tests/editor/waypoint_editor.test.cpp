#include "apcs/animation/arc_length.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/editor/waypoint_editor.h"
#include "apcs/screens/curve_raster.h"

#include <catch2/catch.hpp>

#include <initializer_list>
#include <numeric>

using namespace apcs;
namespace cmd = apcs::command;

namespace {

BoundingBox box_of(std::initializer_list<Vec3> points)
{
    BoundingBox box;
    for (const Vec3& point : points)
        box.add(point);
    return box;
}

const Vec3 origin{0, 0, 0};

struct PathSetup {
    ControlPoints points;
    std::vector<std::size_t> origins;
    PathSettings settings;
    ViewTransform view;
    double step = 1.0;
};

// The thesis' two-point ani1.dat shape: a straight path up, seen from the front (+y right, +z up).
PathSetup two_point_path(ViewAngles angles = {0, 90})
{
    return {{{origin, {0.2, 0.1, -0.3, 0.4}}, {{0, 0, 10}, {}}},
            {0, 1},
            {{1, 1}, 16, 5, Spacing::nearest},
            ViewTransform::fit(angles, std::vector<Vec3>{origin, {0, 0, 10}}, {0, 0, 720, 259}),
            0.1};
}

PathPicture viewed(PathDocument& document, const PathSetup& setup)
{
    PathPicture picture(document, setup.settings);
    picture.set_view(setup.view);
    return picture;
}

// The waypoint editor on a document and its picture, as the path editor opens it.
struct EditedPath {
    explicit EditedPath(const PathSetup& setup)
        : document(setup.points, setup.origins)
        , picture(viewed(document, setup))
        , editor(document, picture, {setup.view, setup.step})
    {
    }
    EditedPath(const EditedPath&) = delete;
    EditedPath& operator=(const EditedPath&) = delete;

    PathDocument document;
    PathPicture picture;
    WaypointEditor editor;
};

// The editor's keys as the path editor's chart gives them to it.
void apply(WaypointEditor& editor, std::initializer_list<Command> commands)
{
    for (const Command& command : commands) {
        if (const auto* choose = std::get_if<cmd::ChoosePoint>(&command))
            editor.choose(choose->by);
        else if (const auto* move = std::get_if<cmd::MovePoint>(&command))
            editor.move(*move);
        else if (std::holds_alternative<cmd::InsertPoint>(command))
            editor.insert();
        else if (std::holds_alternative<cmd::DeletePoint>(command))
            editor.remove();
        else if (std::holds_alternative<cmd::Undo>(command))
            editor.undo();
        else if (std::holds_alternative<cmd::Zoom>(command))
            editor.zoom();
        else
            FAIL("not a key of the waypoint editor");
    }
}

} // namespace

TEST_CASE("a waypoint step is 1 % of the diagonal of what the view shows", "[session][waypoints]")
{
    REQUIRE(waypoint_step(box_of({origin, {0, 0, 10}})) == Approx(0.1));
    REQUIRE(waypoint_step(box_of({origin, {3, 4, 12}, {1, 1, 1}})) == Approx(0.13));
    REQUIRE(waypoint_step(box_of({{5, 5, 5}})) > 0.0);
}

TEST_CASE("I inserts a control point halfway along the curve by arc length, with the chosen point's values",
          "[session][waypoints]")
{
    SECTION("a straight path: the middle of the chord")
    {
        EditedPath path(two_point_path());
        WaypointEditor& editor = path.editor;
        apply(editor, {cmd::InsertPoint{}});
        REQUIRE(editor.points().size() == 3);
        REQUIRE(editor.chosen() == 1);
        REQUIRE(editor.points()[1].position.z == Approx(5.0));
        REQUIRE(editor.points()[1].staff == StaffValues{0.2, 0.1, -0.3, 0.4});
        REQUIRE(editor.origins() == std::vector<std::size_t>{0, new_point, 1});
    }
    SECTION("a bent path: half of the segment's arc length on either side")
    {
        PathSetup setup = two_point_path();
        setup.points.insert(setup.points.begin() + 1, ControlPoint{{0, 6, 3}, {}});
        setup.origins = {0, 1, 2};
        const std::vector<HermiteSegment> before = kb_segments(setup.points, setup.settings.slopes);
        const double first_span = ArcLengthTable(before).length_to_segment_start(1);
        EditedPath path(setup);
        WaypointEditor& editor = path.editor;
        apply(editor, {cmd::InsertPoint{}});
        const Vec3 inserted = editor.points()[1].position;
        const ArcLengthTable table(before);
        const Vec3 expected = table.point_at(table.parameter_at(first_span / 2.0));
        REQUIRE(distance(inserted, expected) < 1e-9);
    }
    SECTION("with the last point chosen: before it")
    {
        EditedPath path(two_point_path());
        WaypointEditor& editor = path.editor;
        apply(editor, {cmd::ChoosePoint{-1}, cmd::InsertPoint{}});
        REQUIRE(editor.points().size() == 3);
        REQUIRE(editor.chosen() == 1);
        REQUIRE(editor.points()[1].position.z == Approx(5.0));
        REQUIRE(editor.points()[1].staff == StaffValues{});
        REQUIRE(editor.points()[2].position.z == 10.0);
    }
}

TEST_CASE("the keypad moves the chosen point in the screen's plane, + and - in depth", "[session][waypoints]")
{
    EditedPath path(two_point_path());
    WaypointEditor& editor = path.editor;
    apply(editor, {cmd::InsertPoint{}});
    REQUIRE(editor.message() == "control point 2 of 3  depth +0.00");
    // Front view: up the screen is +z, right is +y, toward the viewer +x.
    apply(editor, {cmd::MovePoint{0, 1, 0}, cmd::MovePoint{0, 1, 0}, cmd::MovePoint{0, 1, 0}, cmd::MovePoint{0, 1, 0}});
    const Vec3 moved = editor.points()[1].position;
    REQUIRE(moved.x == Approx(0.0).margin(1e-12));
    REQUIRE(moved.y == Approx(0.0).margin(1e-12));
    REQUIRE(moved.z == Approx(5.4));
    apply(editor, {cmd::MovePoint{-3, 0, 0}, cmd::MovePoint{0, 0, +1}, cmd::MovePoint{0, 0, +1}});
    REQUIRE(editor.points()[1].position.y == Approx(-0.3));
    REQUIRE(editor.points()[1].position.x == Approx(0.2));
    REQUIRE(editor.message() == "control point 2 of 3  depth +0.20");
    REQUIRE(editor.change_count() == 8);
}

TEST_CASE("the key frames' points are never moved or deleted, and the message says so", "[session][waypoints]")
{
    EditedPath path(two_point_path());
    WaypointEditor& editor = path.editor;
    const ControlPoints before = editor.points();
    apply(editor, {cmd::MovePoint{0, 1, 0}});
    REQUIRE(editor.message() == "Control point 1 is KEY1's point: it is never moved or deleted");
    apply(editor, {cmd::ChoosePoint{+1}, cmd::DeletePoint{}});
    REQUIRE(editor.message() == "Control point 2 is KEY2's point: it is never moved or deleted");
    REQUIRE(editor.change_count() == 0);
    REQUIRE(editor.points()[0].position == before[0].position);
    REQUIRE(editor.points()[1].position == before[1].position);
    apply(editor, {cmd::ChoosePoint{+1}});
    REQUIRE(editor.message() == "control point 1 of 2  depth +0.00");
}

TEST_CASE("D deletes an interior control point — U and Esc take edits back exactly", "[session][waypoints]")
{
    PathSetup setup = two_point_path();
    setup.points.insert(setup.points.begin() + 1, ControlPoint{{0, 6, 3}, {0.5, 0, 0, 0}});
    setup.origins = {0, 1, 2};
    const ControlPoints original = setup.points;
    EditedPath path(setup);
    WaypointEditor& editor = path.editor;
    apply(editor, {cmd::ChoosePoint{+1}, cmd::DeletePoint{}});
    REQUIRE(editor.points().size() == 2);
    REQUIRE(editor.origins() == std::vector<std::size_t>{0, 2});
    REQUIRE(editor.chosen() == 0);
    apply(editor, {cmd::Undo{}});
    REQUIRE(editor.points().size() == 3);
    REQUIRE(editor.origins() == std::vector<std::size_t>{0, 1, 2});
    REQUIRE(editor.points()[1].staff.tension == 0.5);
    apply(editor, {cmd::Undo{}});
    REQUIRE(editor.message() == "Nothing to undo in the waypoint editor");
    apply(editor, {cmd::InsertPoint{}, cmd::MovePoint{1, 1, 1}, cmd::ChoosePoint{+1}, cmd::DeletePoint{}});
    REQUIRE(path.picture.has_ghost());
    editor.discard();
    REQUIRE_FALSE(path.picture.has_ghost());
    REQUIRE(editor.points().size() == original.size());
    for (std::size_t k = 0; k < original.size(); ++k) {
        REQUIRE(editor.points()[k].position == original[k].position);
        REQUIRE(editor.points()[k].staff == original[k].staff);
    }
    REQUIRE(editor.origins() == std::vector<std::size_t>{0, 1, 2});
}

TEST_CASE("Enter keeps the edits, listed as changes that revert to the points opened with", "[session][waypoints]")
{
    EditedPath path(two_point_path({30, 40}));
    WaypointEditor& editor = path.editor;
    apply(editor, {cmd::InsertPoint{}, cmd::MovePoint{2, -1, 0}, cmd::InsertPoint{}, cmd::MovePoint{0, 0, -1},
                   cmd::ChoosePoint{-1}, cmd::DeletePoint{}});
    ControlPoints points = editor.points();
    std::vector<std::size_t> origins = editor.origins();
    for (auto change = path.document.edits().rbegin(); change != path.document.edits().rend(); ++change)
        revert_change(points, origins, std::get<WaypointChange>(*change));
    const ControlPoints opened = two_point_path().points;
    REQUIRE(points.size() == 2);
    REQUIRE(points[0].position == opened[0].position);
    REQUIRE(points[1].position == opened[1].position);
    REQUIRE(origins == std::vector<std::size_t>{0, 1});
}

TEST_CASE("an insert costs the curve's picture the same work after 4000 inserts as after 200", "[session][waypoints]")
{
    // Each I inserts after the point the last one made: all land in the first segment, as a replay
    // of I held down does (issue 61: 16,000 of them took 17.6 s, each drawing the whole curve).
    EditedPath path(two_point_path());
    WaypointEditor& editor = path.editor;
    const auto insert = [&](int count) {
        for (int i = 0; i < count; ++i)
            apply(editor, {cmd::InsertPoint{}});
    };
    const auto work_of_ten_inserts = [&] {
        const std::size_t before = path.picture.curve_work();
        insert(10);
        return path.picture.curve_work() - before;
    };
    insert(200);
    const std::size_t early = work_of_ten_inserts();
    insert(3790);
    const std::size_t late = work_of_ten_inserts();
    REQUIRE(editor.points().size() == 4012);
    CAPTURE(early, late);
    REQUIRE(early > 0);
    // A block of 64 to 128 segments each (split once they pass 128), the curve's few pixels.
    REQUIRE(late <= 2 * early);
    REQUIRE(late <= 10 * 2 * (2 * CurveRaster::fewest_segments_per_block + 64));
}

TEST_CASE("Esc takes far-apart edits back one at a time: each stays a few segments, none left to refine",
          "[session][waypoints]")
{
    // A change of more segments than a step's waits for the steps (exact spacing's arc lengths):
    // the two take-backs taken together would cover the 2,000 points between them.
    ControlPoints points;
    for (int k = 0; k < 2000; ++k)
        points.push_back({{std::sin(k * 0.9), k * 0.5, std::cos(k * 0.7)}, {}});
    PathDocument document(points);
    const PathSettings settings{{1, 1}, 8, 4, Spacing::exact};
    PathPicture picture(document, settings, PictureRefinement{.when = Refinement::in_steps, .segments_a_step = 64});
    const ViewTransform view = ViewTransform::fit({30, 40}, std::vector<Vec3>{{-1, 0, -1}, {1, 1000, 1}}, {0, 0, 720, 259});
    picture.set_view(view);
    picture.refine();
    WaypointEditor editor(document, picture, {view, 0.1});
    apply(editor, {cmd::ChoosePoint{+1}, cmd::MovePoint{1, 0, 0}, cmd::ChoosePoint{-3}, cmd::MovePoint{1, 0, 0}});
    REQUIRE(editor.chosen() == 1998);
    REQUIRE(editor.change_count() == 2);
    REQUIRE_FALSE(picture.refining());
    editor.discard();
    REQUIRE(editor.change_count() == 0);
    // Back where they were, as a move and its reverse in floating point leave them.
    REQUIRE(length(editor.points()[1].position - points[1].position) < 1e-12);
    REQUIRE(length(editor.points()[1998].position - points[1998].position) < 1e-12);
    REQUIRE_FALSE(picture.refining());
}
