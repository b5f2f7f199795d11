#include "scene/scene_test_support.h"

#include "apcs/animation/arc_length.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/surface_fit.h"
#include "apcs/geometry/bounding_box.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/timed_distance.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <string>
#include <vector>

using namespace apcs;
using apcs::test::DatFiles;
using apcs::test::scene_from;

namespace {

constexpr double tolerance = 1e-9;

bool near(const Vec3& a, const Vec3& b, double within = tolerance) { return distance(a, b) <= within; }

PathSettings exact_settings()
{
    PathSettings settings;
    settings.spacing = Spacing::exact;
    return settings;
}

Vec3 middle(std::span<const Vec3> points)
{
    BoundingBox box;
    box.add(points);
    return box.centre();
}

// The arc length from the curve's start to the curve point nearest `position`: each segment
// scanned at 512 steps of u, then the best step refined by golden-section search.
double arc_length_nearest(const ArcLengthTable& table, std::span<const HermiteSegment> segments, const Vec3& position)
{
    constexpr int steps = 512;
    CurveParameter best;
    double best_distance = distance(segments.front().start, position);
    for (std::size_t s = 0; s < segments.size(); ++s)
        for (int j = 0; j <= steps; ++j) {
            const double u = static_cast<double>(j) / steps;
            const double d = distance(segments[s].point_at(u), position);
            if (d < best_distance) {
                best_distance = d;
                best = {s, u};
            }
        }
    const HermiteSegment& segment = segments[best.segment];
    double low = std::max(0.0, best.u - 1.0 / steps);
    double high = std::min(1.0, best.u + 1.0 / steps);
    const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 100; ++i) {
        const double left = high - golden * (high - low);
        const double right = low + golden * (high - low);
        if (distance(segment.point_at(left), position) < distance(segment.point_at(right), position))
            high = right;
        else
            low = left;
    }
    return table.length_at({best.segment, (low + high) / 2.0});
}

} // namespace

TEST_CASE("frame 0 shows every drawing as it is given", "[scene]")
{
    DatFiles files;
    files.texts["a.dat"] = "0 0 0\n0 1 0\n0 1 1\n";
    files.texts["p.dat"] = "0 0 0\n0 4 1\n0 8 0\n";
    const Scene scene = scene_from("FRAMES 6\nOBJECT a\nSHAPE a.dat\nMOVE p.dat\nROTATE 30\nSCALE 1.5\n", files);
    const SceneAnimation animation(scene, exact_settings());
    const std::vector<Vec3> frame = animation.frame(0);
    REQUIRE(frame == std::vector<Vec3>{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}});
}

TEST_CASE("a wheel point's angle about the wheel's moving centre is rate x frames (seed 003 section 3)", "[scene]")
{
    DatFiles files;
    files.texts["wheel.dat"] = "0 3 1\n0 2 2\n0 1 1\n0 2 0\n"; // a square 'rim' about (0, 2, 1)
    files.texts["bump.dat"] = "0 0 0\n0 5 0\n0 7 1.5\n0 9 0\n";
    const Scene scene = scene_from("FRAMES 40\nOBJECT bicycle\nMOVE bump.dat\n"
                                   "OBJECT wheel PARENT bicycle\nSHAPE wheel.dat\nROTATE -7\n",
                                   files);
    const SceneAnimation animation(scene, exact_settings());
    REQUIRE(near(animation.centre(1), {0, 2, 1}));
    for (int f = 0; f <= 40; ++f) {
        const std::vector<Vec3> points = animation.frame(f);
        const Vec3 centre = animation.transform(1, f)(Vec3{0, 2, 1});
        // The centre moves with the bicycle only: the path's offset.
        REQUIRE(near(centre - Vec3{0, 2, 1}, animation.transform(0, f)(Vec3{})));
        const Vec3 arm = points[0] - centre; // the point that started at angle 0 (along +y)
        const double angle = std::atan2(arm.z, arm.y) * 180.0 / std::numbers::pi;
        const double expected = std::remainder(-7.0 * f, 360.0);
        CAPTURE(f);
        REQUIRE(std::abs(std::remainder(angle - expected, 360.0)) < 1e-9);
        REQUIRE(std::abs(length(arm) - 1.0) < 1e-12);
    }
}

TEST_CASE("a scale about a centre other than the object's moves it by (1-F)(S-C) per frame (seed 003 2.1 (2))",
          "[scene]")
{
    DatFiles files;
    files.texts["box.dat"] = "0 0 0\n0 2 0\n0 2 2\n0 0 2\n"; // centre C = (0, 1, 1)
    const Scene scene = scene_from("FRAMES 8\nOBJECT box\nSHAPE box.dat\nSCALE 0.8 ABOUT 0 5 -3\n", files);
    const SceneAnimation animation(scene, exact_settings());
    const Vec3 about{0, 5, -3};
    const double factor = 0.8;
    Vec3 centre = middle(animation.frame(0));
    for (int f = 1; f <= 8; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> points = animation.frame(f);
        const Vec3 next = middle(points);
        // The seed's dx = (1 − F)(S − C), C the centre before this frame's change.
        REQUIRE(near(next - centre, (about - centre) * (1.0 - factor)));
        centre = next;
        // Its size: the 2 x 2 square's side is 2·0.8^f, in both directions it spans.
        BoundingBox box;
        box.add(points);
        const double side = 2.0 * std::pow(factor, f);
        REQUIRE(std::abs(box.high().y - box.low().y - side) <= tolerance);
        REQUIRE(std::abs(box.high().z - box.low().z - side) <= tolerance);
        REQUIRE(box.high().x - box.low().x <= tolerance);
    }
}

TEST_CASE("a child's change is its parent's followed by its own", "[scene]")
{
    DatFiles files;
    files.texts["dot.dat"] = "0 2 0\n0 3 0\n";
    files.texts["line.dat"] = "0 0 0\n0 10 0\n";
    const Scene scene = scene_from("FRAMES 10\nOBJECT parent\nMOVE line.dat\nROTATE 90 ABOUT 0 0 0\n"
                                   "OBJECT child PARENT parent\nSHAPE dot.dat\nROTATE 90 ABOUT 0 2 0\n",
                                   files);
    const SceneAnimation animation(scene, exact_settings());
    const std::vector<Vec3> frame1 = animation.frame(1);
    // Own: (0,2,0) stays (the centre), (0,3,0) turns to (0,2,1). The parent's turn about x
    // through the origin: (y, z) → (−z, y); then its move of one tenth of the line, (0, 1, 0).
    REQUIRE(near(frame1[0], {0, 1, 2}));
    REQUIRE(near(frame1[1], {0, 0, 2}));
    // Frame 2: own turn 180° (0,3,0) → (0,1,0); parent's 180° → (0,−1,0); move (0,2,0) → (0,1,0).
    REQUIRE(near(animation.frame(2)[1], {0, 1, 0}));
}

TEST_CASE("MOVE without TIMES spreads the path over FROM ... TO by its acceleration law — LOOP starts each lap at P0",
          "[scene]")
{
    DatFiles files;
    files.texts["dot.dat"] = "0 0 0\n";
    files.texts["line.dat"] = "0 0 0\n0 10 0\n";
    const Scene scene = scene_from("FRAMES 20\nOBJECT a\nSHAPE dot.dat\nMOVE line.dat FROM 2 TO 7 LOOP\n", files);
    const SceneAnimation animation(scene, exact_settings());
    const double expected[] = {0, 0, 0, 2, 4, 6, 8, 0, 2, 4, 6, 8, 0, 2, 4, 6, 8, 0, 2, 4, 6};
    for (int f = 0; f <= 20; ++f) {
        CAPTURE(f);
        REQUIRE(std::abs(animation.frame(f)[0].y - expected[f]) < 1e-6);
    }
    const Scene held = scene_from("FRAMES 9\nOBJECT a\nSHAPE dot.dat\nMOVE line.dat TO 5\n", files);
    const SceneAnimation held_animation(held, exact_settings());
    REQUIRE(held_animation.frame(9)[0] == Vec3{0, 10, 0});
    // Acceleration +1 (ease-in) in the path's 7th column: the first step is the law's 1 − cos(π/2 · 1/5).
    files.texts["fast.dat"] = "0 0 0 0 0 0 1\n0 10 0 0 0 0 1\n";
    const Scene eased = scene_from("FRAMES 5\nOBJECT a\nSHAPE dot.dat\nMOVE fast.dat\n", files);
    const SceneAnimation eased_animation(eased, exact_settings());
    REQUIRE(std::abs(eased_animation.frame(1)[0].y - 10 * (1 - std::cos(std::numbers::pi / 10))) < 1e-6);
}

TEST_CASE("a scene without SPACING moves at even steps (exact): a MOVE along a 2-point road in 36 frames never "
          "stands still - SPACING nearest does, every 9th frame, and --spacing overrides the line",
          "[scene]")
{
    DatFiles files;
    files.texts["dot.dat"] = "0 0 0\n";
    files.texts["road.dat"] = "0 0 0\n0 10 0\n";
    const auto steps = [&](const std::string& spacing_line, std::optional<Spacing> given) {
        const Scene scene = scene_from("FRAMES 36\n" + spacing_line + "OBJECT car\nSHAPE dot.dat\nMOVE road.dat\n", files);
        PathSettings command;
        if (given)
            command.spacing = *given;
        const SceneAnimation animation(scene, scene_path_settings(scene, command, given.has_value()));
        std::vector<double> step;
        for (int f = 1; f <= 36; ++f)
            step.push_back(animation.frame(f)[0].y - animation.frame(f - 1)[0].y);
        return step;
    };
    for (const double step : steps("", std::nullopt))
        REQUIRE(std::abs(step - 10.0 / 36) < 1e-9);
    // Nearest on 32 samples a span: 1.125 samples a frame, so every 9th frame repeats its sample.
    const std::vector<double> nearest = steps("SPACING nearest\n", std::nullopt);
    std::vector<int> still;
    for (std::size_t f = 0; f < nearest.size(); ++f)
        if (nearest[f] == 0)
            still.push_back(static_cast<int>(f) + 1);
    REQUIRE(still == std::vector<int>{5, 14, 23, 32});
    REQUIRE(steps("", Spacing::nearest) == nearest);
    for (const double step : steps("SPACING nearest\n", Spacing::exact))
        REQUIRE(std::abs(step - 10.0 / 36) < 1e-9);
}

TEST_CASE("a part without STAFF moves by its parent's four-line values, one with STAFF by its own (Ch. 3.3)",
          "[scene]")
{
    DatFiles files;
    files.texts["dot.dat"] = "0 0 0\n";
    files.texts["line.dat"] = "0 0 0\n0 10 0\n"; // three columns: the part's staff values apply
    const auto first_step = [&files](const std::string& part_staff) {
        const Scene scene = scene_from("FRAMES 5\nOBJECT body\nSTAFF 0 0 0 1\nOBJECT dot PARENT body\n" + part_staff +
                                           "SHAPE dot.dat\nMOVE line.dat\n",
                                       files);
        return SceneAnimation(scene, exact_settings()).frame(1)[0].y;
    };
    // Inherited acceleration +1 (ease-in): the law's 1 − cos(π/2 · 1/5) of the span, not the even 1/5.
    CHECK(std::abs(first_step("") - 10 * (1 - std::cos(std::numbers::pi / 10))) < 1e-6);
    CHECK(std::abs(first_step("STAFF 0 0 0 0\n") - 2.0) < 1e-6);
}

TEST_CASE("timed waypoints: each control point at its frame, never running back, no jump of speed at a key",
          "[scene]")
{
    DatFiles files;
    files.texts["dot.dat"] = "0 0 0\n";
    files.texts["road.dat"] = "0 0 0\n0 10 3\n0 25 0\n0 40 2\n";
    const Scene scene = scene_from("FRAMES 70\nOBJECT car\nSHAPE dot.dat\nMOVE road.dat TIMES 0 10 35 60\n", files);
    const SceneAnimation animation(scene, exact_settings());
    const ControlPoints& road = scene.objects[0].move->path;
    const int times[] = {0, 10, 35, 60};
    for (std::size_t k = 0; k < 4; ++k)
        REQUIRE(animation.frame(times[k])[0] == road[k].position);
    REQUIRE(animation.frame(70)[0] == road.back().position);
    // Distance along the curve: the arc length at each frame's position, found on the curve itself,
    // is S(f) of the distance-time function through the keys and never decreases. S itself comes
    // from TimedDistance, which the next test holds to its properties; here the frames are held
    // to it, and at the keys (above) to the control points by hand.
    const std::vector<HermiteSegment> segments = kb_segments(road, EndSlopes{});
    const ArcLengthTable table(segments);
    std::vector<double> keys(4);
    for (std::size_t k = 0; k < 4; ++k)
        keys[k] = table.length_to_segment_start(k);
    const TimedDistance law(times, keys);
    std::vector<double> step(61);
    double previous = 0.0;
    for (int f = 0; f <= 60; ++f) {
        CAPTURE(f);
        const Vec3 position = animation.frame(f)[0];
        const double travelled = arc_length_nearest(table, segments, position);
        REQUIRE(std::abs(travelled - law.at(f)) < 1e-6);
        REQUIRE(travelled >= previous);
        previous = travelled;
        if (f > 0)
            step[static_cast<std::size_t>(f)] = distance(animation.frame(f - 1)[0], position);
    }
    for (const int key : {10, 35}) {
        CAPTURE(key);
        const double before = step[static_cast<std::size_t>(key)];
        const double after = step[static_cast<std::size_t>(key + 1)];
        REQUIRE(std::abs(after - before) <= 0.2 * before);
    }
}

TEST_CASE("the distance-time function is monotone with a continuous slope — piecewise-even spacing would jump",
          "[scene]")
{
    const int frames[] = {0, 10, 35, 60};
    const double distances[] = {0, 10, 35, 45};
    const TimedDistance distance(frames, distances);
    for (std::size_t k = 0; k < 4; ++k)
        REQUIRE(distance.at(frames[k]) == distances[k]);
    for (double f = 0; f < 60; f += 0.25)
        REQUIRE(distance.at(f + 0.25) >= distance.at(f));
    // Average speeds 1, 1 and 0.4: at frame 35 the ratio is 2.5, the largest the contract allows.
    const double before = distance.at(35) - distance.at(34);
    const double after = distance.at(36) - distance.at(35);
    REQUIRE(std::abs(after - before) <= 0.2 * before);
    REQUIRE(std::abs(after - 0.4) > 0.2 * 0.4); // not the next span's even step
    // A span that does not move holds still: slope 0 at both its ends, no overshoot.
    const double flat[] = {0, 5, 5, 9};
    const TimedDistance stop(frames, flat);
    REQUIRE(stop.slope_at_key(1) == 0.0);
    REQUIRE(stop.slope_at_key(2) == 0.0);
    for (double f = 10; f <= 35; f += 0.5)
        REQUIRE(stop.at(f) == Approx(5.0));
}

TEST_CASE("a joint the key frames would break moves the part, and its parts, with its parent", "[scene]")
{
    DatFiles files;
    files.texts["upper1.dat"] = "0 0 4\n0 0 2\n";
    files.texts["upper2.dat"] = "0 0 4\n0 2 4\n";
    files.texts["lower1.dat"] = "0 0 2\n0 0 0\n";
    files.texts["lower2.dat"] = "0 2 4\n0 4 4\n";
    files.texts["foot.dat"] = "0 0 0\n0 1 0\n";
    files.texts["hip.dat"] = "0 0 4\n0 0 4\n";
    // The knee swings on a circle about the hip; the lower limb's own knee runs straight.
    files.texts["knee.dat"] = "0 0 2\n0 1.4142135623730951 2.585786437626905\n0 2 4\n";
    const Scene scene = scene_from("FRAMES 8\nOBJECT upper\nKEYS upper1.dat upper2.dat\nPATHS hip.dat knee.dat\n"
                                   "JOINT knee 2\nOBJECT lower PARENT upper\nKEYS lower1.dat lower2.dat\nJOINT knee 1\n"
                                   "JOINT ankle 2\nOBJECT foot PARENT lower\nSHAPE foot.dat\nJOINT ankle 1\n",
                                   files);
    const SceneAnimation animation(scene, exact_settings());
    const double joint_tolerance = default_joint_tolerance(scene);
    bool moved = false;
    for (int f = 0; f <= 8; ++f) {
        const std::vector<Vec3> points = animation.frame(f);
        CAPTURE(f);
        REQUIRE(distance(points[1], points[2]) <= joint_tolerance); // the knee
        REQUIRE(distance(points[3], points[4]) <= joint_tolerance); // the ankle
        moved = moved || !near(points[2], animation.transform(1, f)(scene.objects[1].keys->keys.key1.all_points()[0]), 1e-6);
    }
    REQUIRE(moved);
}

TEST_CASE("a KEYS object is fitted by the construction asked for: the thesis' Ferguson surface or the blend",
          "[scene][keys]")
{
    // Three points along y; KEY2 the same moved along x. The first path bows out in z, the last
    // runs straight: the interior point's path depends on the construction.
    DatFiles files;
    files.texts["k1.dat"] = "0 0 0\n0 2 0\n0 4 0\n";
    files.texts["k2.dat"] = "6 0 0\n6 2 0\n6 4 0\n";
    files.texts["first.dat"] = "0 0 0\n3 0 3\n6 0 0\n";
    files.texts["last.dat"] = "0 4 0\n6 4 0\n";
    const Scene scene = scene_from("FRAMES 6\nOBJECT sheet\nKEYS k1.dat k2.dat\nPATHS first.dat last.dat\n", files);
    PathSettings settings = exact_settings();
    const SceneAnimation ferguson(scene, settings, SurfaceConstruction::ferguson);
    const SceneAnimation blend(scene, settings);
    // FROM 0 TO 6: five in-betweens, as apcs fit --inbetweens 5 makes them.
    settings.inbetween_count = 5;
    const SceneKeys& keys = *scene.objects[0].keys;
    const EvaluatedPath first = evaluate_path(keys.first_path, settings);
    const EvaluatedPath last = evaluate_path(keys.last_path, settings);
    const FrameSequence by_ferguson = fit_key_frames(keys.keys, first, last, SurfaceConstruction::ferguson);
    const FrameSequence by_blend = fit_key_frames(keys.keys, first, last);
    double apart = 0;
    for (int f = 0; f <= 6; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> ferguson_points = ferguson.frame(f);
        const std::vector<Vec3> blend_points = blend.frame(f);
        for (std::size_t i = 0; i < 3; ++i) {
            REQUIRE(near(ferguson_points[i], by_ferguson.frame(static_cast<std::size_t>(f))[i]));
            REQUIRE(near(blend_points[i], by_blend.frame(static_cast<std::size_t>(f))[i]));
        }
        apart = std::max(apart, distance(ferguson_points[1], blend_points[1]));
    }
    REQUIRE(apart > 0.01);
}

TEST_CASE("SCALE FX FY FZ scales each axis of the scene by its own factor per frame (Net_Anim's ExtendX/ExtendY)",
          "[scene]")
{
    DatFiles files;
    files.texts["box.dat"] = "1 1 1\n3 3 3\n"; // centre (2, 2, 2)
    const Scene scene = scene_from("FRAMES 2\nOBJECT box\nSHAPE box.dat\nSCALE 1 2 0.5 ABOUT 0 0 0 FROM 0 TO 2\n", files);
    REQUIRE(scene.objects[0].scale->factors == Vec3{1, 2, 0.5});
    const SceneAnimation animation(scene, exact_settings());
    // Frame f: x·1^f, y·2^f, z·0.5^f about the origin.
    for (int f = 0; f <= 2; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> points = animation.frame(f);
        const double y = std::pow(2.0, f);
        const double z = std::pow(0.5, f);
        REQUIRE(near(points[0], Vec3{1, y, z}));
        REQUIRE(near(points[1], Vec3{3, 3 * y, 3 * z}));
    }
}

TEST_CASE("JOINT NAME I-J joins at the centroid of a contact region of points", "[scene][joints]")
{
    // The body's joint is the middle of its points 2-3, (0, 1, 0), where the arm's point 1 is drawn.
    // The arm turns about its own centre each frame; the joint brings its point 1 back there.
    DatFiles files;
    files.texts["body.dat"] = "0 0 0\n0 0 0\n0 2 0\n0 2 2\n";
    files.texts["arm.dat"] = "0 1 0\n0 2 0\n";
    const Scene scene = scene_from("FRAMES 2\nOBJECT body\nSHAPE body.dat\nJOINT hand 2-3\n"
                                   "OBJECT arm PARENT body\nSHAPE arm.dat\nROTATE 90 AXIS x\nJOINT hand 1\n",
                                   files);
    REQUIRE(scene.objects[0].joints[0].point == 1);
    REQUIRE(scene.objects[0].joints[0].last_point == 2);
    const SceneAnimation animation(scene, exact_settings());
    for (int f = 0; f <= 2; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> points = animation.frame(f);
        REQUIRE(near(points[4], Vec3{0, 1, 0}));
        REQUIRE(std::abs(distance(points[4], points[5]) - 1.0) < tolerance);
    }
    // Turned 90° about x, the arm points along ±z at frame 1, not along y.
    REQUIRE(std::abs(animation.frame(1)[5].y - 1.0) < 1e-9);
}

TEST_CASE("MOVE ALIGN turns the object with the path's tangent about the point that rides it", "[scene][align]")
{
    // A KB arc from (0, 0, 0) to (0, 5, 5) in the y-z plane: end slopes 1 make its end tangents the
    // first and last chords, at 22.5° and 67.5° above +y. A stick drawn along +y from the rider at
    // P_0 turns with the tangent: by 45° at the end, to (0, cos 45°, sin 45°).
    DatFiles files;
    files.texts["arc.dat"] = "0 0 0\n0 3.5355339 1.4644661\n0 5 5\n";
    files.texts["stick.dat"] = "0 0 0\n0 1 0\n";
    const Scene scene = scene_from("FRAMES 4\nOBJECT s\nSHAPE stick.dat\nMOVE arc.dat ALIGN\n", files);
    REQUIRE(scene.objects[0].move->align);
    REQUIRE_FALSE(scene.objects[0].move->ahead);
    const SceneAnimation animation(scene, exact_settings());
    REQUIRE(near(animation.frame(0)[1], Vec3{0, 1, 0}));
    for (int f = 0; f <= 4; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> points = animation.frame(f);
        REQUIRE(std::abs(distance(points[0], points[1]) - 1.0) < 1e-9);
        REQUIRE(std::abs(points[1].x) < 1e-9);
    }
    const std::vector<Vec3> end = animation.frame(4);
    REQUIRE(near(end[0], Vec3{0, 5, 5}));
    // The polyline's last segment stands for the end tangent: within 0.01 of it.
    REQUIRE(distance(end[1] - end[0], Vec3{0, std::sqrt(0.5), std::sqrt(0.5)}) < 0.01);
}

TEST_CASE("MOVE ALIGN AHEAD D keeps both axles of a two-axle vehicle on the path", "[scene][align]")
{
    // A bowl z = (y − 5)² / 10 through 21 control points; the rear axle rides it from (0, 0, 2.5),
    // the front axle is drawn 2 ahead on it (the first of 2000 samples a segment 2 away or more).
    // In every frame both axles are on the curve.
    DatFiles files;
    std::string bowl;
    ControlPoints control;
    for (int k = 0; k <= 20; ++k) {
        const double y = 0.5 * k;
        const double z = (y - 5) * (y - 5) / 10;
        bowl += "0 " + std::to_string(y) + " " + std::to_string(z) + "\n";
        control.push_back({{0, std::stod(std::to_string(y)), std::stod(std::to_string(z))}, {}});
    }
    files.texts["bowl.dat"] = bowl;
    PathSettings dense = exact_settings();
    dense.samples_per_segment = 2000;
    dense.inbetween_count = 0;
    const std::vector<Vec3> curve = evaluate_path(control, dense).curve.samples();
    const auto off_curve = [&curve](const Vec3& point) {
        double nearest = distance(curve.front(), point);
        for (const Vec3& sample : curve)
            nearest = std::min(nearest, distance(sample, point));
        return nearest;
    };
    const Vec3 rear = curve.front();
    std::size_t k = 0;
    while (distance(curve[k], rear) < 2.0)
        ++k;
    const Vec3 front = curve[k];
    files.texts["car.dat"] = "0 0 2.5\n0 " + std::to_string(front.y) + " " + std::to_string(front.z) + "\n";
    const Scene scene = scene_from("FRAMES 30\nOBJECT car\nSHAPE car.dat\nMOVE bowl.dat ALIGN AHEAD 2\n", files);
    REQUIRE(scene.objects[0].move->ahead == 2.0);
    const SceneAnimation animation(scene, exact_settings());
    std::size_t checked = 0;
    for (int f = 0; f <= 30; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> points = animation.frame(f);
        REQUIRE(off_curve(points[0]) < 1e-3);
        REQUIRE(std::abs(distance(points[0], points[1]) - distance(rear, front)) < 1e-5); // rigid (6 decimals)
        // Near the end the path has no point 2 ahead: the last direction is kept (SPEC 8.1).
        if (distance(points[0], curve.back()) < 2.0)
            continue;
        REQUIRE(off_curve(points[1]) < 2e-3);
        ++checked;
    }
    REQUIRE(checked > 20);
}

TEST_CASE("ALIGN on a path of zero length, AHEAD without a distance or below it are refused with the line",
          "[scene][align]")
{
    DatFiles files;
    files.texts["still.dat"] = "0 1 1\n0 1 1\n";
    files.texts["stick.dat"] = "0 1 1\n0 2 1\n";
    const auto refused = [&files](const std::string& text) {
        const Expected<Scene> scene = parse_scene(text, "t.scn", files.reader(), {});
        REQUIRE_FALSE(scene);
        return scene.error().to_string();
    };
    const std::string head = "FRAMES 5\nOBJECT s\nSHAPE stick.dat\n";
    CHECK(refused(head + "MOVE still.dat ALIGN\n") ==
          "t.scn:4: ALIGN on 'still.dat', a path of zero length: it has no direction to turn the object by");
    CHECK(refused(head + "MOVE stick.dat ALIGN AHEAD\n") ==
          "t.scn:4: expected 'ALIGN AHEAD D' with D the distance between the axles");
    CHECK(refused(head + "MOVE stick.dat ALIGN AHEAD 0\n") ==
          "t.scn:4: ALIGN AHEAD '0' is not above 0; expected the distance between the axles");
    CHECK(refused(head + "MOVE stick.dat ALIGN ALIGN\n") == "t.scn:4: ALIGN is given twice; expected it once");
}
