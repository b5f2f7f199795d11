#include "apcs/editor/path_document.h"
#include "apcs/editor/path_picture.h"
#include "apcs/animation/view_transform.h"
#include "support/same_path.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;

namespace {

ControlPoints three_points()
{
    return {{{0, 0, 0}, {0.5, 0, 0, 0}}, {{0, 3, 4}, {0.5, 0, 0, 0}}, {{0, 0, 10}, {0.5, 0, 0, 0}}};
}

} // namespace

TEST_CASE("a path document: every change of its points advances its revision, a change of nothing does not",
          "[editor][document]")
{
    PathDocument document(three_points());
    REQUIRE(document.origins() == std::vector<std::size_t>{0, 1, 2});
    REQUIRE(document.revision() == 0);
    const ControlRegion whole{0, 2};

    const PathDocument::StaffSet tighter = document.set_staff(whole, {0.6, 0, 0, 0});
    REQUIRE(tighter.changed);
    REQUIRE(document.revision() == 1);
    REQUIRE(document.points()[1].staff.tension == 0.6);
    // The same values again (a step past the end of a line) change no point.
    REQUIRE_FALSE(document.set_staff(whole, {0.6, 0, 0, 0}).changed);
    REQUIRE(document.revision() == 1);

    document.restore_staff(whole, tighter.runs_before);
    REQUIRE(document.points()[1].staff.tension == 0.5);
    REQUIRE(document.revision() == 2);
}

TEST_CASE("a staff key's change is told from the region's runs as apply_staff_to_region leaves the points",
          "[editor][document]")
{
    // Point by point, what staff_runs reads after the key, against what the document says.
    const auto changes_as_the_points_do = [](ControlRegion region, const StaffValues& staff) {
        PathDocument document(three_points());
        const std::vector<StaffRun> before = staff_runs(document.points(), region);
        const bool changed = document.set_staff(region, staff).changed;
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
    WaypointChange insert;
    insert.kind = WaypointChange::Kind::insert;
    insert.index = 1;
    insert.point = {{0, 1, 1}, {}};
    const PathChange inserted = document.apply(insert);
    REQUIRE(inserted.inserted == 1);
    document.record(insert);
    REQUIRE(document.points().size() == 4);
    REQUIRE(document.origins() == std::vector<std::size_t>{0, new_point, 1, 2});

    WaypointChange move;
    move.kind = WaypointChange::Kind::move;
    move.index = 2;
    move.offset = {0, 0, 1};
    document.apply(move);
    document.record(move);
    REQUIRE(document.points()[2].position == Vec3{0, 3, 5});
    REQUIRE(document.edit_count() == 2);
    REQUIRE(document.revision() == 2);

    // Newest first, as U takes them back.
    document.revert(std::get<WaypointChange>(document.take_last_edit()));
    document.revert(std::get<WaypointChange>(document.take_last_edit()));
    REQUIRE(document.edit_count() == 0);
    REQUIRE(document.origins() == std::vector<std::size_t>{0, 1, 2});
    const ControlPoints original = three_points();
    for (std::size_t k = 0; k < original.size(); ++k)
        REQUIRE(document.points()[k].position == original[k].position);
    REQUIRE(document.revision() == 4);
}

TEST_CASE("a path picture reads its document: refreshed after a change it is the picture of the changed points, "
          "and its revision follows the document's",
          "[editor][document]")
{
    PathDocument document(three_points());
    const PathSettings settings{{1, 1}, 8, 4, Spacing::nearest};
    PathPicture picture(document, settings);
    REQUIRE(picture.revision().document == 0);
    WaypointChange move;
    move.kind = WaypointChange::Kind::move;
    move.index = 1;
    move.offset = {0, 2, 0};
    picture.refresh(document.apply(move));
    REQUIRE(picture.revision().document == document.revision());
    // What a picture made afresh of the document shows, to the bit.
    const PathPicture afresh(document, settings);
    REQUIRE(picture.evaluated().curve.segments.size() == afresh.evaluated().curve.segments.size());
    for (std::size_t k = 0; k < afresh.evaluated().curve.segments.size(); ++k) {
        const HermiteSegment& kept = picture.evaluated().curve.segments[k];
        const HermiteSegment& made = afresh.evaluated().curve.segments[k];
        REQUIRE((kept.start == made.start && kept.end == made.end && kept.start_tangent == made.start_tangent &&
                 kept.end_tangent == made.end_tangent));
    }
}

TEST_CASE("a picture nobody sees evaluates the path as one that is seen, and draws no curve, ghost or reference",
          "[editor][document][issue57]")
{
    PathDocument seen_document(three_points());
    PathDocument unseen_document(three_points());
    const PathSettings settings{{1, 1}, 8, 4, Spacing::nearest};
    PathPicture seen(seen_document, settings);
    PathPicture unseen(unseen_document, settings, PictureRefinement{.seen = false});
    const std::vector<Vec3> scene{{-5, -5, -5}, {5, 5, 5}};
    const ViewTransform view = ViewTransform::fit({30, 40}, scene, {0, 0, 720, 348});
    seen.set_view(view);
    unseen.set_view(view);
    WaypointChange move;
    move.kind = WaypointChange::Kind::move;
    move.index = 1;
    move.offset = {0, 2, 0};
    make_waypoint_edit(seen_document, seen, move);
    make_waypoint_edit(unseen_document, unseen, move);
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
    const PathDocument document(points);
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
