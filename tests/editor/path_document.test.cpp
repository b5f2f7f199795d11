#include "apcs/editor/path_document.h"
#include "apcs/editor/path_picture.h"
#include "apcs/animation/view_transform.h"
#include "apcs/screens/path_screen.h"
#include "support/same_path.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;

namespace {

ControlPoints three_points()
{
    return {{{0, 0, 0}, {0.5, 0, 0, 0}}, {{0, 3, 4}, {0.5, 0, 0, 0}}, {{0, 0, 10}, {0.5, 0, 0, 0}}};
}

WaypointChange moved(std::size_t index, Vec3 offset)
{
    WaypointChange move;
    move.kind = WaypointChange::Kind::move;
    move.index = index;
    move.offset = offset;
    return move;
}

WaypointChange inserted(std::size_t index, Vec3 position)
{
    WaypointChange insert;
    insert.kind = WaypointChange::Kind::insert;
    insert.index = index;
    insert.point = {position, {}};
    return insert;
}

// The box from (-5, -5, -5) to (5, 5, 5) filling the raster, seen from theta 30, phi 40.
ViewTransform box_view()
{
    return ViewTransform::fit({30, 40}, std::vector<Vec3>{{-5, -5, -5}, {5, 5, 5}}, {0, 0, 720, 348});
}

} // namespace

namespace {

// A staff key on `region` with the staff shown as `shown` before it (on the TENSION line).
StaffEdit staff_key(ControlRegion region, const StaffValues& shown) { return {region, StaffLine::tension, shown, 0.0, {}}; }

} // namespace

TEST_CASE("a path document: every change of its points advances its revision, an edit joins its history and U "
          "takes it out, a change of nothing does neither",
          "[editor][document]")
{
    PathDocument document(three_points());
    REQUIRE(document.origins() == std::vector<std::size_t>{0, 1, 2});
    REQUIRE(document.revision() == 0);
    const ControlRegion whole{0, 2};
    const StaffValues shown{0.5, 0, 0, 0};

    const std::optional<PathChange> tighter = document.set_staff(staff_key(whole, shown), {0.6, 0, 0, 0});
    REQUIRE(tighter.has_value());
    REQUIRE((tighter->first == 0 && tighter->removed == 3 && tighter->inserted == 3));
    REQUIRE(tighter->what == PathChange::What::staff);
    REQUIRE(document.revision() == 1);
    REQUIRE(document.edit_count() == 1);
    REQUIRE(document.points()[1].staff.tension == 0.6);
    // The same values again, the staff shown already at them (a step past the end of a line).
    const StaffValues now{0.6, 0, 0, 0};
    REQUIRE_FALSE(document.set_staff(staff_key(whole, now), now).has_value());
    REQUIRE(document.revision() == 1);
    REQUIRE(document.edit_count() == 1);
    // An acceleration moves no segment.
    REQUIRE(document.set_staff(staff_key(whole, now), {0.6, 0, 0, 0.5})->what == PathChange::What::accelerations);

    // U takes back the newest first, each a change of its own.
    REQUIRE(std::get<StaffEdit>(document.undo()).staff == now);
    REQUIRE(document.points()[1].staff.acceleration == 0.0);
    REQUIRE(std::get<StaffEdit>(document.undo()).staff == shown);
    REQUIRE(document.points()[1].staff.tension == 0.5);
    REQUIRE(document.revision() == 4);
    REQUIRE(document.edit_count() == 0);
}

TEST_CASE("a staff key's change is told from the region's runs as apply_staff_to_region leaves the points",
          "[editor][document]")
{
    // Point by point, what staff_runs reads after the key, against what the document says (the
    // staff shown already at the values: only a point's change makes an edit).
    const auto changes_as_the_points_do = [](ControlRegion region, const StaffValues& staff) {
        PathDocument document(three_points());
        const std::vector<StaffRun> before = staff_runs(document.points(), region);
        const bool changed = document.set_staff(staff_key(region, staff), staff).has_value();
        REQUIRE(changed == (staff_runs(document.points(), region) != before));
        return changed;
    };
    // A lone interior point keeps its own acceleration (no span starts there): a new one changes nothing.
    REQUIRE_FALSE(changes_as_the_points_do({1, 1}, {0.5, 0, 0, 0.3}));
    REQUIRE(changes_as_the_points_do({1, 1}, {0.4, 0, 0, 0}));
    // Points 1 and 2: the first takes the acceleration, the last keeps its own.
    REQUIRE(changes_as_the_points_do({0, 1}, {0.5, 0, 0, 0.3}));
    REQUIRE_FALSE(changes_as_the_points_do({0, 1}, {0.5, 0, 0, 0}));
    // The whole path: every point, the last included, takes it.
    REQUIRE(changes_as_the_points_do({0, 2}, {0.5, 0, 0, 0.3}));
    REQUIRE_FALSE(changes_as_the_points_do({0, 2}, {0.5, 0, 0, 0}));
    // Values beyond the staff are clamped to it first.
    REQUIRE_FALSE(changes_as_the_points_do({0, 2}, {0.5, 0, 0, -0.0}));
}

TEST_CASE("a path document's waypoint edits revert exactly, origins with them, and its history is the edits in order",
          "[editor][document]")
{
    PathDocument document(three_points());
    const WaypointChange insert = inserted(1, {0, 1, 1});
    const PathChange inserted = document.apply(insert);
    REQUIRE(inserted.inserted == 1);
    REQUIRE(document.points().size() == 4);
    REQUIRE(document.origins() == std::vector<std::size_t>{0, new_point, 1, 2});

    const WaypointChange move = moved(2, {0, 0, 1});
    document.apply(move);
    REQUIRE(document.points()[2].position == Vec3{0, 3, 5});
    REQUIRE(document.edit_count() == 2);
    REQUIRE(document.revision() == 2);

    // Newest first, as U takes them back.
    REQUIRE(std::get<WaypointChange>(document.undo()).kind == WaypointChange::Kind::move);
    REQUIRE(std::get<WaypointChange>(document.undo()).kind == WaypointChange::Kind::insert);
    REQUIRE(document.edit_count() == 0);
    REQUIRE(document.origins() == std::vector<std::size_t>{0, 1, 2});
    const ControlPoints original = three_points();
    for (std::size_t k = 0; k < original.size(); ++k)
        REQUIRE(document.points()[k].position == original[k].position);
    REQUIRE(document.revision() == 4);
}

// Worked by hand from the ranges: each change's points in the points between the two.
TEST_CASE("two changes as one: the range covering both, from the points before the first to those after the second",
          "[editor][document]")
{
    using What = PathChange::What;
    // Point 5 moved, then point 2 deleted: between them 5..5 and 2..2; before, 2..5 (4 points);
    // after, 2..4 (3 points).
    const PathChange moved_then_deleted = combined({5, 1, 1, What::positions}, {2, 1, 0, What::positions});
    REQUIRE((moved_then_deleted.first == 2 && moved_then_deleted.removed == 4 && moved_then_deleted.inserted == 3));
    // A point inserted at 3 (none by one), then points 1..2 given a tension: between them 1..3;
    // before, 1..2; after, 1..3.
    const PathChange inserted_then_staff = combined({3, 0, 1, What::positions}, {1, 2, 2, What::staff});
    REQUIRE((inserted_then_staff.first == 1 && inserted_then_staff.removed == 2 && inserted_then_staff.inserted == 3));
    REQUIRE(inserted_then_staff.what == What::positions);
    // Two accelerations far apart: the points between are covered, still no segment.
    const PathChange far_apart = combined({0, 1, 1, What::accelerations}, {9, 1, 1, What::accelerations});
    REQUIRE((far_apart.first == 0 && far_apart.removed == 10 && far_apart.inserted == 10));
    REQUIRE(far_apart.what == What::accelerations);
}

namespace {

// The picture's segments are those of a picture made afresh of the document, to the bit.
void require_picture_of(PathPicture& picture, const PathDocument& document, const PathSettings& settings)
{
    PointsPicture afresh(document.points(), settings);
    const auto& kept = picture.evaluated().curve.segments;
    const auto& made = afresh.evaluated().curve.segments;
    REQUIRE(kept.size() == made.size());
    for (std::size_t k = 0; k < made.size(); ++k)
        REQUIRE((kept[k].start == made[k].start && kept[k].end == made[k].end &&
                 kept[k].start_tangent == made[k].start_tangent && kept[k].end_tangent == made[k].end_tangent));
}

} // namespace

TEST_CASE("a path picture pulls its document's changes: told nothing, it is the picture of the points as they are, "
          "its ghost the curve before the changes it took together",
          "[editor][document]")
{
    PathDocument document(three_points());
    const PathSettings settings{{1, 1}, 8, 4, Spacing::nearest};
    PathPicture picture(document, settings);
    const ViewTransform view = box_view();
    picture.set_view(view);
    const std::uint64_t revision = picture.revision();

    const WaypointChange insert = inserted(1, {0, 1, 2});
    const WaypointChange move = moved(3, {0, 2, 0});
    document.apply(insert);
    document.apply(move);
    // Read after both: one catch-up.
    REQUIRE(picture.revision() == revision + 1);
    require_picture_of(picture, document, settings);
    REQUIRE(picture.has_ghost());
    // The ghost's pixels (the screen with it, less the screen without) lie on the curve of the
    // points before both changes, none off it: not the curve between them.
    PathScreenContent content = path_screen_content(document.points(), picture.evaluated());
    const Bitmap without_ghost = picture.draw(content).bitmap;
    content.ghost = true;
    const Bitmap with_ghost = picture.draw(content).bitmap;
    PathDocument before(three_points());
    PathPicture of_before(before, settings);
    of_before.set_view(view);
    const Bitmap was = of_before.draw(path_screen_content(before.points(), of_before.evaluated())).bitmap;
    std::size_t ghost_pixels = 0;
    std::size_t off_the_curve_before = 0;
    for (int y = 0; y < was.height(); ++y)
        for (int x = 0; x < was.width(); ++x)
            if (with_ghost.get(x, y) && !without_ghost.get(x, y)) {
                ++ghost_pixels;
                off_the_curve_before += !was.get(x, y);
            }
    REQUIRE(ghost_pixels > 20);
    REQUIRE(off_the_curve_before == 0);

    // Another reader took the changes: the picture is made again whole, without a ghost.
    const std::uint64_t seen = document.revision();
    document.undo();
    REQUIRE(document.take_changes(seen).has_value());
    require_picture_of(picture, document, settings);
    REQUIRE_FALSE(picture.has_ghost());
}

TEST_CASE("a picture nobody sees evaluates the path as one that is seen, and draws no curve, ghost or reference",
          "[editor][document][issue57]")
{
    PathDocument seen_document(three_points());
    PathDocument unseen_document(three_points());
    const PathSettings settings{{1, 1}, 8, 4, Spacing::nearest};
    PathPicture seen(seen_document, settings);
    PathPicture unseen(unseen_document, settings, PictureRefinement{.seen = false});
    const ViewTransform view = box_view();
    seen.set_view(view);
    unseen.set_view(view);
    const WaypointChange move = moved(1, {0, 2, 0});
    seen_document.apply(move);
    unseen_document.apply(move);
    unseen.pin_reference("A");
    const auto& kept = unseen.evaluated().curve;
    const auto& shown = seen.evaluated().curve;
    REQUIRE(kept.segments.size() == shown.segments.size());
    for (std::size_t k = 0; k < kept.segments.size(); ++k)
        REQUIRE((kept.segments[k].start == shown.segments[k].start && kept.segments[k].end == shown.segments[k].end &&
                 kept.segments[k].start_tangent == shown.segments[k].start_tangent &&
                 kept.segments[k].end_tangent == shown.segments[k].end_tangent));
    REQUIRE(unseen.evaluated().inbetweens.size() == seen.evaluated().inbetweens.size());
    // The seen picture keeps the curve before the move as its ghost; the unseen one drew nothing
    // to keep, and is never left refining.
    REQUIRE(seen.has_ghost());
    REQUIRE_FALSE(unseen.has_ghost());
    REQUIRE_FALSE(unseen.refining());
}

// The arrays a session makes while a long path's slopes prompt waits (make_room) are the ones the
// picture evaluates into, and the evaluation is the one made without them (PERFORMANCE.md 19).
TEST_CASE("a path picture made with arrays made ahead evaluates into them, to the bit as one made without",
          "[editor][document]")
{
    ControlPoints points;
    for (int k = 0; k < 3000; ++k)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.5, std::cos(k * 0.7) * 4.0},
                          {k % 7 == 0 ? -0.5 : 0.2, std::sin(k * 0.3) * 0.4, 0.1, k < 1500 ? 0.0 : 0.45}});
    PathDocument document(points);
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact})
        for (const Refinement when : {Refinement::at_once, Refinement::in_steps}) {
            CAPTURE(static_cast<int>(spacing), static_cast<int>(when));
            const PathSettings settings{{1, 0.5}, 16, 12, spacing};
            EvaluatedPath room;
            std::size_t steps = 1;
            while (!make_room(room, points.size(), 1000))
                ++steps;
            REQUIRE(steps == 3); // 2,999 segments, 1,000 a step
            REQUIRE(has_room(room, points.size()));
            const HermiteSegment* made = room.curve.segments.data();
            const double* lengths = room.curve.length_to_point.data();
            PathPicture picture(document, settings, PictureRefinement{.when = when}, std::move(room));
            picture.refine();
            PathPicture without(document, settings, PictureRefinement{.when = when});
            without.refine();
            REQUIRE(picture.evaluated().curve.segments.data() == made);
            REQUIRE(picture.evaluated().curve.length_to_point.data() == lengths);
            test::require_same_path(picture.evaluated(), without.evaluated());
        }
}

TEST_CASE("a second reader asking from too far back is made again whole, and leaves the first reader its changes",
          "[editor][document]")
{
    PathDocument document(three_points());
    const PathSettings settings{{1, 1}, 8, 4, Spacing::nearest};
    PathPicture first(document, settings);
    PathPicture second(document, settings);
    const ViewTransform view = box_view();
    first.set_view(view);
    second.set_view(view);
    const WaypointChange move = moved(1, {0, 1, 0});
    document.apply(move);
    first.catch_up(); // the first takes change 1
    document.apply(move);
    // The second asks from revision 0: change 1 is gone, so it is made again whole, without a ghost.
    require_picture_of(second, document, settings);
    REQUIRE_FALSE(second.has_ghost());
    // Change 2 stayed for the first, whose ghost is the curve before it.
    require_picture_of(first, document, settings);
    REQUIRE(first.has_ghost());
}
