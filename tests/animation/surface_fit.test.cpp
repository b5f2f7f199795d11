#include "apcs/animation/hermite.h"
#include "apcs/animation/surface_fit.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace apcs;

namespace {

ControlPoints path_through(std::initializer_list<Vec3> positions)
{
    ControlPoints points;
    for (const Vec3& position : positions)
        points.push_back({position, {}});
    return points;
}

Graphic open_graphic(std::vector<Vec3> points)
{
    Graphic graphic;
    graphic.parts.push_back({"g", Closure::open, std::move(points)});
    return graphic;
}

// `graphic` moved by `d` (a translation).
Graphic moved(Graphic graphic, const Vec3& d)
{
    for (Vec3& point : graphic.parts.front().points)
        point = point + d;
    return graphic;
}

const PathSettings settings{{}, 16, 5, Spacing::nearest};

} // namespace

TEST_CASE("frame 0 is KEY1, frame M+1 is KEY2 and the end points follow their paths", "[animation][fit]")
{
    const Graphic key1 = open_graphic({{0, 0, 0}, {0, 2, 1}, {0, 4, 0}, {0, 6, 3}});
    const Graphic key2 = open_graphic({{5, 1, 0}, {6, 3, 0}, {5, 5, 2}, {7, 8, 1}});
    const EqualisedKeys keys{key1, key2};
    const EvaluatedPath first = evaluate_path(path_through({{0, 0, 0}, {2, -2, 1}, {5, 1, 0}}), settings);
    const EvaluatedPath last = evaluate_path(path_through({{0, 6, 3}, {4, 9, 2}, {7, 8, 1}}), settings);
    const FrameSequence frames = fit_key_frames(keys, first, last);
    REQUIRE(frames.frame_count() == 7);
    REQUIRE(frames.points_per_frame() == 4);
    const auto frame0 = frames.frame(0);
    const auto frame6 = frames.frame(6);
    REQUIRE(std::vector<Vec3>(frame0.begin(), frame0.end()) == key1.all_points());
    REQUIRE(std::vector<Vec3>(frame6.begin(), frame6.end()) == key2.all_points());
    for (std::size_t k = 1; k <= 5; ++k) {
        REQUIRE(frames.frame(k)[0] == first.inbetweens[k - 1].position);
        REQUIRE(frames.frame(k)[3] == last.inbetweens[k - 1].position);
    }
}

TEST_CASE("an interior point worked by hand from the blend of SPEC 5.3", "[animation][fit]")
{
    // KEY1 (0,0,0) (1,0,0) (4,0,0): chord places 0, 1/4, 1; KEY2 (0,10,0) (1,10,0) (2,10,0): 0, 1/2, 1.
    // The middle point's v = (1/4 + 1/2) / 2 = 3/8; F1(3/8) = 2·27/512 − 3·9/64 + 1 = 350/512,
    // F2(3/8) = 162/512. Edges at frame 1 given directly: E0 = (0,4,2) at progress 1/4,
    // E1 = (3,6,0) at progress 3/4.
    const std::vector<Vec3> key1{{0, 0, 0}, {1, 0, 0}, {4, 0, 0}};
    const std::vector<Vec3> key2{{0, 10, 0}, {1, 10, 0}, {2, 10, 0}};
    const EdgePath first{{{0, 0, 0}, {0, 4, 2}, {0, 10, 0}}, {0.0, 0.25, 1.0}};
    const EdgePath last{{{4, 0, 0}, {3, 6, 0}, {2, 10, 0}}, {0.0, 0.75, 1.0}};
    const FrameSequence frames = fit_surface(key1, key2, Closure::open, first, last);
    // w = 350/512 · 1/4 + 162/512 · 3/4 = 209/512; lerp((1,0,0), (1,10,0), w) = (1, 2090/512, 0).
    // D0 = (0,4,2) − lerp((0,0,0), (0,10,0), 1/4) = (0, 1.5, 2);
    // D1 = (3,6,0) − lerp((4,0,0), (2,10,0), 3/4) = (3,6,0) − (2.5, 7.5, 0) = (0.5, −1.5, 0).
    // P = (1 + 162/512·0.5, 2090/512 + (350 − 162)/512·1.5, 350/512·2)
    //   = (593/512, 2372/512, 700/512).
    const Vec3 expected{593.0 / 512.0, 2372.0 / 512.0, 700.0 / 512.0};
    REQUIRE(distance(frames.frame(1)[1], expected) < 1e-12);
}

TEST_CASE("straight edge paths at even steps move every point along its own line at even steps",
          "[animation][fit]")
{
    // The N to L example of the session with the split's straight ani1 and ani4 paths, all values 0.
    EqualisedKeys keys = equalise_key_frames(open_graphic({{0, 0, 0}, {0, 0, 10}, {0, 6, 0}, {0, 6, 10}}),
                                             open_graphic({{0, 0, 10}, {0, 0, 0}, {0, 5, 0}}));
    const std::vector<Vec3> key1 = keys.key1.all_points();
    const std::vector<Vec3> key2 = keys.key2.all_points();
    const PathSettings exact{{}, 32, 12, Spacing::exact};
    const EvaluatedPath first = evaluate_path(path_through({key1.front(), key2.front()}), exact);
    const EvaluatedPath last = evaluate_path(path_through({key1.back(), key2.back()}), exact);
    const FrameSequence frames = fit_key_frames(keys, first, last);
    REQUIRE(frames.frame_count() == 14);
    for (std::size_t i = 0; i < key1.size(); ++i) {
        const Vec3 whole_way = key2[i] - key1[i];
        for (std::size_t k = 1; k < frames.frame_count(); ++k) {
            CAPTURE(i, k);
            // Every step is 1/13 of the way from KEY1 to KEY2: on the line, monotonic, even.
            const Vec3 step = frames.frame(k)[i] - frames.frame(k - 1)[i];
            REQUIRE(distance(step, whole_way * (1.0 / 13.0)) < 1e-9);
        }
    }
}

TEST_CASE("a still edge point makes no neighbour jump: no step exceeds 1.5 times the median step",
          "[animation][fit]")
{
    // Example 3 as one graphic: an apple that stays (its first point's path has zero length) and a
    // snake that moves five units on.
    Graphic key1;
    key1.parts = {{"apple", Closure::closed, {{0, 14, 3.2}, {0, 15.2, 2}, {0, 14, 0.8}, {0, 12.8, 2}}},
                  {"snake", Closure::open, {{0, 0, 0}, {0, 2, 0}, {0, 4, 0}, {0, 6, 0}}}};
    Graphic key2;
    key2.parts = {{"apple", Closure::closed, {{0, 14, 3.2}, {0, 15.2, 2}, {0, 14, 0.8}, {0, 12.8, 2}}},
                  {"snake", Closure::open, {{0, 5, 0}, {0, 7, 0.5}, {0, 9, 0}, {0, 11.6, 0.9}}}};
    const EqualisedKeys keys{key1, key2};
    const PathSettings exact{{}, 32, 12, Spacing::exact};
    const EvaluatedPath still = evaluate_path(path_through({{0, 14, 3.2}, {0, 14, 3.2}}), exact);
    const EvaluatedPath head = evaluate_path(path_through({{0, 6, 0}, {0, 8.5, 2}, {0, 11.6, 0.9}}), exact);
    const FrameSequence frames = fit_key_frames(keys, still, head);
    for (std::size_t i = 0; i < frames.points_per_frame(); ++i) {
        std::vector<double> steps;
        for (std::size_t k = 1; k < frames.frame_count(); ++k)
            steps.push_back(distance(frames.frame(k)[i], frames.frame(k - 1)[i]));
        std::vector<double> sorted = steps;
        std::sort(sorted.begin(), sorted.end());
        const double median = sorted[sorted.size() / 2];
        CAPTURE(i, median, sorted.back());
        REQUIRE(sorted.back() <= 1.5 * median + 1e-12);
    }
}

TEST_CASE("v is the chord-length place along the graphic, averaged over both keys", "[animation][fit]")
{
    const std::vector<Vec3> key1{{0, 0, 0}, {1, 0, 0}, {4, 0, 0}};
    const std::vector<Vec3> key2{{0, 0, 0}, {3, 0, 0}, {4, 0, 0}};
    const std::vector<double> v = graphic_parameters(key1, key2, Closure::open);
    REQUIRE(v[0] == 0.0);
    REQUIRE(v[1] == Approx(0.5));
    REQUIRE(v[2] == 1.0);
    // Closed: the closing segment (4 back to 0) counts, so the last point sits at 4/8.
    const std::vector<double> wrapped = graphic_parameters(key1, key1, Closure::closed);
    REQUIRE(wrapped[2] == Approx(0.5));
}

TEST_CASE("a closed graphic stays closed in every frame and uses the first path only", "[animation][fit]")
{
    Graphic ring;
    ring.parts.push_back({"ring", Closure::closed, {{0, 0, 0}, {0, 2, 0}, {0, 2, 2}, {0, 0, 2}, {0, 0, 0}}});
    Graphic moved;
    moved.parts.push_back({"ring", Closure::closed, {{4, 1, 0}, {4, 4, 0}, {4, 4, 3}, {4, 1, 3}, {4, 1, 0}}});
    const EvaluatedPath first = evaluate_path(path_through({{0, 0, 0}, {2, -3, 1}, {4, 1, 0}}), settings);
    // Two second paths as unlike as can be: neither may change a single point of any frame.
    const EvaluatedPath ignored = evaluate_path(path_through({{9, 9, 9}, {8, 8, 8}}), settings);
    const EvaluatedPath other = evaluate_path(path_through({{0, 0, 0}, {-5, 7, 2}, {1, -6, 9}, {4, 1, 0}}), settings);
    const FrameSequence frames = fit_key_frames({ring, moved}, first, ignored);
    const FrameSequence again = fit_key_frames({ring, moved}, first, other);
    REQUIRE(frames.frame_count() == 7);
    REQUIRE(again.frame_count() == frames.frame_count());
    const std::vector<Vec3> key1 = ring.all_points();
    const std::vector<Vec3> key2 = moved.all_points();
    const EdgePath edge = edge_path_from(first, key1.front(), key2.front());
    for (std::size_t k = 0; k < frames.frame_count(); ++k) {
        const auto frame = frames.frame(k);
        REQUIRE(frame.front() == frame.back());
        if (k > 0 && k + 1 < frames.frame_count())
            REQUIRE(frame.front() == first.inbetweens[k - 1].position);
        // With E1 = E0 and w1 = w0 the blend across the graphic is one: every point is
        // lerp(K1_i, K2_i, w0) plus the first path's bend off its chord.
        const Vec3 bend = edge.positions[k] - lerp(key1.front(), key2.front(), edge.progress[k]);
        for (std::size_t i = 0; i < frames.points_per_frame(); ++i) {
            CAPTURE(k, i);
            REQUIRE(again.frame(k)[i] == frame[i]);
            REQUIRE(distance(frame[i], lerp(key1[i], key2[i], edge.progress[k]) + bend) < 1e-12);
        }
    }
    // v wraps: the closing segment counts, so a ring of four corners puts its last one at 3/4
    // (and a ring that repeats its first point ends at 1, where it began).
    const std::vector<Vec3> corners(key1.begin(), key1.end() - 1);
    const std::vector<Vec3> moved_corners(key2.begin(), key2.end() - 1);
    CHECK(graphic_parameters(corners, moved_corners, Closure::closed) == std::vector<double>{0.0, 0.25, 0.5, 0.75});
    CHECK(graphic_parameters(key1, key2, Closure::closed) == std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0});
    CHECK(graphic_parameters(corners, moved_corners, Closure::open) ==
          std::vector<double>{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0});
}

TEST_CASE("a key whose points all coincide places them by index, v_i = i/(n-1)", "[animation][fit]")
{
    const std::vector<Vec3> dot{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    const std::vector<Vec3> line{{0, 0, 0}, {0, 1, 0}, {0, 3, 0}, {0, 6, 0}}; // chord places 0, 1/6, 1/2, 1
    CHECK(graphic_parameters(dot, dot, Closure::open) == std::vector<double>{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0});
    // Averaged with the other key's chord places: (1/3 + 1/6)/2 = 1/4, (2/3 + 1/2)/2 = 7/12.
    const std::vector<double> v = graphic_parameters(dot, line, Closure::open);
    REQUIRE(v.size() == 4);
    CHECK(v[0] == 0.0);
    CHECK(v[1] == Approx(0.25).epsilon(1e-15));
    CHECK(v[2] == Approx(7.0 / 12.0).epsilon(1e-15));
    CHECK(v[3] == 1.0);

    // A fit from a key that is one point: KEY1's places 0, 1/2, 1, KEY2's 0, 1/4, 1, so the middle
    // point's v = 3/8 as in the hand-worked blend above: straight edges at progress 1/4 and 3/4 give
    // w = 350/512 · 1/4 + 162/512 · 3/4 = 209/512 and P = lerp((0,0,0), (1,0,4), 209/512).
    const std::vector<Vec3> point{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    const std::vector<Vec3> bar{{0, 0, 4}, {1, 0, 4}, {4, 0, 4}};
    const EdgePath first{{{0, 0, 0}, {0, 0, 1}, {0, 0, 4}}, {0.0, 0.25, 1.0}};
    const EdgePath last{{{0, 0, 0}, {3, 0, 3}, {4, 0, 4}}, {0.0, 0.75, 1.0}};
    const FrameSequence frames = fit_surface(point, bar, Closure::open, first, last);
    REQUIRE(distance(frames.frame(1)[1], Vec3{209.0 / 512.0, 0.0, 836.0 / 512.0}) < 1e-12);
}

TEST_CASE("the chord along a graphic of several parts runs through the pen-up jumps, in file order",
          "[animation][fit]")
{
    // Parts a (0,0,0)-(0,1,0) and b (0,4,0)-(0,5,0): the jump of 3 between them counts, so
    // v = 0, 1/5, 4/5, 1 (leaving it out would give 0, 1/2, 1/2, 1).
    Graphic key1;
    key1.parts = {{"a", Closure::open, {{0, 0, 0}, {0, 1, 0}}}, {"b", Closure::open, {{0, 4, 0}, {0, 5, 0}}}};
    Graphic key2;
    key2.parts = {{"a", Closure::open, {{6, 0, 0}, {6, 1, 0}}}, {"b", Closure::open, {{6, 4, 0}, {6, 5, 0}}}};
    const std::vector<Vec3> points1 = key1.all_points();
    const std::vector<Vec3> points2 = key2.all_points();
    const double v[] = {0.0, 0.2, 0.8, 1.0};
    // A straight first path and a last path that rises out of the plane: the interior points take
    // F2(v) of its bend, so each shows its own v.
    const EvaluatedPath first = evaluate_path(path_through({{0, 0, 0}, {6, 0, 0}}), settings);
    const EvaluatedPath last = evaluate_path(path_through({{0, 5, 0}, {3, 5, 3}, {6, 5, 0}}), settings);
    const FrameSequence frames = fit_key_frames({key1, key2}, first, last);
    const EdgePath edge0 = edge_path_from(first, points1.front(), points2.front());
    const EdgePath edge1 = edge_path_from(last, points1.back(), points2.back());
    REQUIRE(frames.frame_count() == 7);
    for (std::size_t k = 1; k + 1 < frames.frame_count(); ++k) {
        const Vec3 bend0 = edge0.positions[k] - lerp(points1.front(), points2.front(), edge0.progress[k]);
        const Vec3 bend1 = edge1.positions[k] - lerp(points1.back(), points2.back(), edge1.progress[k]);
        for (std::size_t i = 0; i < 4; ++i) {
            const HermiteBasis across = hermite_basis(v[i]);
            const double w = across.f1 * edge0.progress[k] + across.f2 * edge1.progress[k];
            const Vec3 expected = lerp(points1[i], points2[i], w) + bend0 * across.f1 + bend1 * across.f2;
            CAPTURE(k, i);
            REQUIRE(distance(frames.frame(k)[i], expected) < 1e-12);
        }
        // Point 1 rises by F2(1/5) = 0.104 of the bend, point 2 by F2(4/5) = 0.896 of it.
        REQUIRE(frames.frame(k)[2].z > frames.frame(k)[1].z);
    }
}

TEST_CASE("a graphic of several parts is fitted as one sequence", "[animation][fit]")
{
    Graphic key1;
    key1.parts = {{"a", Closure::open, {{0, 0, 0}, {0, 1, 0}}}, {"b", Closure::open, {{0, 3, 0}, {0, 4, 0}}}};
    Graphic key2;
    key2.parts = {{"a", Closure::open, {{5, 0, 0}, {5, 1, 1}}}, {"b", Closure::open, {{5, 3, 1}, {5, 4, 0}}}};
    const EvaluatedPath first = evaluate_path(path_through({{0, 0, 0}, {5, 0, 0}}), settings);
    const EvaluatedPath last = evaluate_path(path_through({{0, 4, 0}, {5, 4, 0}}), settings);
    const FrameSequence frames = fit_key_frames({key1, key2}, first, last);
    REQUIRE(frames.points_per_frame() == 4);
    REQUIRE(frames.frame(frames.frame_count() - 1)[2] == Vec3{5, 3, 1});
    // Straight paths at equal speed move every point at the same pace: x grows alike for all.
    for (std::size_t k = 1; k + 1 < frames.frame_count(); ++k)
        for (std::size_t i = 1; i < 4; ++i)
            REQUIRE(frames.frame(k)[i].x == Approx(frames.frame(k)[0].x));
}

// SPEC §5.3.1, the thesis' Ferguson surface (Ch. 3.2, fig. 3.2.1).

TEST_CASE("a 3-point key's interior Ferguson path has the zero-twist end tangents worked by hand",
          "[animation][fit][ferguson]")
{
    // KEY1 (0,0,0) (1,0,0) (2,0,0): the middle point's v1 = 1/2, F1 = F2 = 1/2.
    // KEY2 (0,0,2) (0.5,0,2) (2,0,2): v2 = 0.5/2 = 1/4, F1(1/4) = 2/64 − 3/16 + 1 = 0.84375, F2 = 0.15625.
    // First path (0,0,0) → (0,0,2), slopes 0.5 1: T_first,start = 0.5·(0,0,2) = (0,0,1),
    // T_first,end = (0,0,2). Last path (2,0,0) → (3,0,1) → (2,0,2), slopes 0.5 1:
    // T_last,start = 0.5·(1,0,1) = (0.5,0,0.5), T_last,end = (2,0,2) − (3,0,1) = (−1,0,1).
    const PathSettings slopes{{0.5, 1.0}, 16, 5, Spacing::nearest};
    const EvaluatedPath first = evaluate_path(path_through({{0, 0, 0}, {0, 0, 2}}), slopes);
    const EvaluatedPath last = evaluate_path(path_through({{2, 0, 0}, {3, 0, 1}, {2, 0, 2}}), slopes);
    const FergusonCorners corners{edge_tangents_of(first), edge_tangents_of(last)};
    REQUIRE(corners.first.start == Vec3{0, 0, 1});
    REQUIRE(corners.first.end == Vec3{0, 0, 2});
    REQUIRE(corners.last.start == Vec3{0.5, 0, 0.5});
    REQUIRE(corners.last.end == Vec3{-1, 0, 1});
    const std::vector<Vec3> key1{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    const std::vector<Vec3> key2{{0, 0, 2}, {0.5, 0, 2}, {2, 0, 2}};
    const std::vector<HermiteSegment> paths = ferguson_point_paths(key1, key2, Closure::open, corners);
    REQUIRE(paths.size() == 3);
    const HermiteSegment& middle = paths[1];
    REQUIRE(middle.start == Vec3{1, 0, 0});
    REQUIRE(middle.end == Vec3{0.5, 0, 2});
    // Pu1(1/2) = 0.5·(0,0,1) + 0.5·(0.5,0,0.5) = (0.25, 0, 0.75).
    REQUIRE(distance(middle.start_tangent, Vec3{0.25, 0, 0.75}) < 1e-15);
    // Pu2(1/4) = 0.84375·(0,0,2) + 0.15625·(−1,0,1) = (−0.15625, 0, 1.84375).
    REQUIRE(distance(middle.end_tangent, Vec3{-0.15625, 0, 1.84375}) < 1e-15);
    // The end points' own paths get their own corners' tangents (v = 0 and v = 1).
    REQUIRE(paths[0].start_tangent == Vec3{0, 0, 1});
    REQUIRE(paths[2].end_tangent == Vec3{-1, 0, 1});
}

TEST_CASE("a translated key with straight 2-point edges and slopes 1: every Ferguson path is its chord",
          "[animation][fit][ferguson]")
{
    // KEY2 = KEY1 + d, d = (1,2,3); both edges 2-point with slopes 1, so every corner tangent is d
    // and Pu1 = Pu2 = (F1 + F2)·d = d: the Hermite segment K1 → K1 + d with tangents d is the chord.
    const Vec3 d{1, 2, 3};
    const Graphic key1 = open_graphic({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {3, 1, 0}});
    const Graphic key2 = moved(key1, d);
    const EqualisedKeys keys{key1, key2};
    const PathSettings exact{{}, 32, 6, Spacing::exact};
    const EvaluatedPath first = evaluate_path(path_through({{0, 0, 0}, {1, 2, 3}}), exact);
    const EvaluatedPath last = evaluate_path(path_through({{3, 1, 0}, {4, 3, 3}}), exact);
    const FrameSequence frames = fit_key_frames(keys, first, last, SurfaceConstruction::ferguson);
    REQUIRE(frames.frame_count() == 8);
    for (std::size_t i = 0; i < 4; ++i) {
        double previous = 0.0;
        for (std::size_t k = 1; k < 8; ++k) {
            const Vec3 moved = frames.frame(k)[i] - key1.parts.front().points[i];
            // On the chord: moved = s·d for one s, growing from frame to frame.
            const double along = dot(moved, d) / dot(d, d);
            REQUIRE(distance(moved, along * d) < 1e-9);
            REQUIRE(along > previous);
            previous = along;
        }
    }
}

TEST_CASE("Ferguson in-betweens lie at F1(v)·w0 + F2(v)·w1 of each path, w0 and w1 the edges' own progress",
          "[animation][fit][ferguson]")
{
    // A translation with straight 2-point edges: every path is its chord (the test above), so the
    // arc fraction reached is the share of the move. KEY1's chord places 0, 1/4, 3/4, 1 (lengths
    // 1, 2, 1 of 4) are KEY2's too: v = 1/4 gives F1 = 0.84375, F2 = 0.15625. The first edge
    // accelerates (+0.8) and the last slows (−0.8), so w0 ≠ w1 in every in-between: a point placed
    // by w0 alone, or by v1 for v, would miss.
    const Vec3 d{0, 2, 0};
    const Graphic key1 = open_graphic({{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0}});
    const Graphic key2 = moved(key1, d);
    ControlPoints first_path = path_through({{0, 0, 0}, {0, 2, 0}});
    first_path.front().staff.acceleration = 0.8;
    ControlPoints last_path = path_through({{4, 0, 0}, {4, 2, 0}});
    last_path.front().staff.acceleration = -0.8;
    const PathSettings exact{{}, 32, 6, Spacing::exact};
    const EvaluatedPath first = evaluate_path(first_path, exact);
    const EvaluatedPath last = evaluate_path(last_path, exact);
    const std::vector<double> w0 = edge_path_from(first, {0, 0, 0}, {0, 2, 0}).progress;
    const std::vector<double> w1 = edge_path_from(last, {4, 0, 0}, {4, 2, 0}).progress;
    const FrameSequence frames = fit_key_frames({key1, key2}, first, last, SurfaceConstruction::ferguson);
    REQUIRE(frames.frame_count() == 8);
    const double f1[] = {1.0, 0.84375, 0.15625, 0.0};
    for (std::size_t k = 1; k + 1 < 8; ++k) {
        CAPTURE(k);
        REQUIRE(std::abs(w0[k] - w1[k]) > 0.01);
        for (std::size_t i = 1; i < 3; ++i) {
            const double along = (frames.frame(k)[i] - key1.parts.front().points[i]).y / d.y;
            REQUIRE(std::abs(along - (f1[i] * w0[k] + (1.0 - f1[i]) * w1[k])) < 1e-9);
        }
    }
}

TEST_CASE("KEY1 along y and KEY2 along z: the Ferguson paths bend off their chords",
          "[animation][fit][ferguson]")
{
    // KEY1 (0,0,0) (0,1,0) (0,4,0): v1 = 1/4; KEY2 (1,0,0) (1,0,1) (1,0,4): v2 = 1/4.
    // Edges 2-point, slopes 1: d0 = (1,0,0), d1 = (1,0,4) − (0,4,0) = (1,−4,4).
    // Pu1 = Pu2 = 0.84375·d0 + 0.15625·d1 = (1, −0.625, 0.625); the chord is (1,−1,1).
    // P(u) = K1 + F2(u)·chord + (F3(u) + F4(u))·T with F3 + F4 = u(2u − 1)(u − 1) = 0.09375 at
    // u = 1/4: P(1/4) = (0,1,0) + 0.15625·(1,−1,1) + 0.09375·(1,−0.625,0.625)
    //                = (0.25, 0.78515625, 0.21484375), off the chord.
    const std::vector<Vec3> key1{{0, 0, 0}, {0, 1, 0}, {0, 4, 0}};
    const std::vector<Vec3> key2{{1, 0, 0}, {1, 0, 1}, {1, 0, 4}};
    const PathSettings plain{{}, 16, 5, Spacing::nearest};
    const FergusonCorners corners{edge_tangents_of(evaluate_path(path_through({key1[0], key2[0]}), plain)),
                                  edge_tangents_of(evaluate_path(path_through({key1[2], key2[2]}), plain))};
    const HermiteSegment middle = ferguson_point_paths(key1, key2, Closure::open, corners)[1];
    REQUIRE(distance(middle.start_tangent, Vec3{1, -0.625, 0.625}) < 1e-15);
    REQUIRE(distance(middle.end_tangent, Vec3{1, -0.625, 0.625}) < 1e-15);
    const Vec3 quarter = middle.point_at(0.25);
    REQUIRE(distance(quarter, Vec3{0.25, 0.78515625, 0.21484375}) < 1e-15);
    // Off the chord by (0.25, −0.21484375, 0.21484375) − (0.6796875 / 3)·(1,−1,1)
    // = (3/128, 3/256, −3/256), a distance of 3·√6 / 256.
    const Vec3 chord = key2[1] - key1[1];
    const Vec3 off = quarter - key1[1];
    REQUIRE(std::abs(distance(off, dot(off, chord) / dot(chord, chord) * chord) - 3.0 * std::sqrt(6.0) / 256.0) < 1e-15);
}

TEST_CASE("the point at an arc fraction of a straight segment is that share of it — of a still segment, its start",
          "[animation][fit][ferguson]")
{
    // A straight segment (tangents equal to its chord) has arc fraction = parameter share, so the
    // point at fraction 0.3 of (0,0,0) → (10,0,0) is (3,0,0); a segment of no length gives its start.
    const HermiteSegment straight{{0, 0, 0}, {10, 0, 0}, {10, 0, 0}, {10, 0, 0}};
    REQUIRE(distance(point_at_arc_fraction(straight, 0.3), Vec3{3, 0, 0}) < 1e-8);
    const HermiteSegment still{{1, 1, 1}, {1, 1, 1}, {}, {}};
    REQUIRE(point_at_arc_fraction(still, 0.5) == Vec3{1, 1, 1});
}

TEST_CASE("a measured segment places arc fractions as the adaptive Simpson measuring does, near-cusps included",
          "[animation][fit][ferguson]")
{
    // Issue 45: each Ferguson point was placed by Newton's steps on an adaptive Simpson sum (about
    // 25 us a point and frame); the knot table and Gauss-Legendre must land where that did, to
    // 1e-10 of the length, on gentle segments, loops and near-cusps (a tangent against the chord).
    const HermiteSegment segments[] = {
        {{0, 0, 0}, {5, 3, 1}, {2, 3, 4}, {3, -2, 9}},
        {{0, 0, 0}, {1, 0, 0}, {10, 10, 0}, {10, -10, 0}},      // a loop
        {{0, 0, 0}, {1, 0, 0}, {-3, 0.001, 0}, {-3, 0.001, 0}}, // doubles back: near-cusps
        {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 0}},           // still at both ends
    };
    for (const HermiteSegment& segment : segments) {
        CurveArcLengths adaptive;
        adaptive.measure(std::span(&segment, 1));
        const double total = adaptive.total_length();
        const MeasuredSegment measured(segment);
        for (int step = 0; step <= 40; ++step) {
            const double fraction = step / 40.0;
            const Vec3 expected = segment.point_at(adaptive.parameter_at(std::span(&segment, 1), fraction * total).u);
            INFO("segment from " << segment.start.x << " fraction " << fraction);
            REQUIRE(distance(measured.at_arc_fraction(fraction), expected) <= 1e-10 * total);
        }
    }
    // Out and back along x: P(u) = (2 + u(1 - u), 2, 2), its speed |1 - 2u| zero at the turn.
    // The arc length is known exactly (0.5 in all): the point at fraction f is 2 + 0.5f out, or
    // back from 2.25. (The adaptive Simpson search missed it by 2e-5 just past the turn.)
    const HermiteSegment out_and_back{{2, 2, 2}, {2, 2, 2}, {1, 0, 0}, {-1, 0, 0}};
    const MeasuredSegment measured(out_and_back);
    for (int step = 0; step <= 40; ++step) {
        const double travelled = 0.5 * step / 40.0;
        const double x = 2.0 + (travelled <= 0.25 ? travelled : 0.5 - travelled);
        INFO("travelled " << travelled);
        REQUIRE(distance(measured.at_arc_fraction(step / 40.0), Vec3{x, 2, 2}) <= 1e-10);
    }
}
