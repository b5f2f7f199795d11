#include "apcs/animation/surface_fit.h"

#include <catch2/catch.hpp>

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

TEST_CASE("an interior point worked by hand from the Coons formula", "[animation][fit]")
{
    // Three points; v by chord length: KEY1 (0,0,0) (1,0,0) (3,0,0) → 0, 1/3, 1; KEY2 the same
    // shape moved by (0,10,0) → v = 1/3 for the middle point. Edge positions at frame 1 given
    // directly with progress 0.5 for both.
    const std::vector<Vec3> key1{{0, 0, 0}, {1, 0, 0}, {3, 0, 0}};
    const std::vector<Vec3> key2{{0, 10, 0}, {1, 10, 0}, {3, 10, 0}};
    const EdgePath first{{{0, 0, 0}, {0, 4, 2}, {0, 10, 0}}, {0.0, 0.5, 1.0}};
    const EdgePath last{{{3, 0, 0}, {3, 6, 0}, {3, 10, 0}}, {0.0, 0.5, 1.0}};
    const FrameSequence frames = fit_surface(key1, key2, Closure::open, first, last);
    // F1(1/3) = 2/27 − 3/9 + 1 = 20/27, F2(1/3) = 7/27; F1(0.5) = F2(0.5) = 0.5.
    // Key shape terms: K1_1 − 20/27·(0,0,0) − 7/27·(3,0,0) = (1 − 21/27, 0, 0) = (6/27, 0, 0);
    // K2_1 − 20/27·(0,10,0) − 7/27·(3,10,0) = (6/27, 0, 0).
    // P = 20/27·(0,4,2) + 7/27·(3,6,0) + 0.5·(6/27,0,0) + 0.5·(6/27,0,0) = (27/27, 122/27, 40/27).
    const Vec3 expected{1.0, 122.0 / 27.0, 40.0 / 27.0};
    REQUIRE(distance(frames.frame(1)[1], expected) < 1e-12);
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
    const EvaluatedPath ignored = evaluate_path(path_through({{9, 9, 9}, {8, 8, 8}}), settings);
    const FrameSequence frames = fit_key_frames({ring, moved}, first, ignored);
    for (std::size_t k = 0; k < frames.frame_count(); ++k) {
        const auto frame = frames.frame(k);
        REQUIRE(frame.front() == frame.back());
        if (k > 0 && k + 1 < frames.frame_count())
            REQUIRE(frame.front() == first.inbetweens[k - 1].position);
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
