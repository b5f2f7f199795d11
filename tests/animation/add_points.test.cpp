#include "apcs/animation/add_points.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;

namespace {

// Every original point appears, in order, and every other point lies on the original segment
// between the originals around it.
void require_refines(const std::vector<Vec3>& original, const std::vector<Vec3>& refined)
{
    std::size_t next = 0;
    for (std::size_t i = 0; i < refined.size(); ++i) {
        if (next < original.size() && refined[i] == original[next]) {
            ++next;
            continue;
        }
        REQUIRE(next > 0);
        REQUIRE(next < original.size());
        const Vec3 a = original[next - 1];
        const Vec3 b = original[next];
        // On the segment: |a−p| + |p−b| = |a−b|.
        REQUIRE(distance(a, refined[i]) + distance(refined[i], b) == Approx(distance(a, b)));
    }
    REQUIRE(next == original.size());
}

GraphicPart part_of(std::vector<Vec3> points, std::string name = "p")
{
    return {std::move(name), Closure::open, std::move(points)};
}

} // namespace

TEST_CASE("Algorithm 2 from 3 to 8 points: the first segment gets 3 points, the second 2", "[animation][addpoint]")
{
    // RT = (8−1) div (3−1) = 3, RS = 7 mod 2 = 1.
    const std::vector<Vec3> small{{0, 0, 0}, {8, 0, 0}, {8, 6, 0}};
    const std::vector<Vec3> padded = add_points(small, 8);
    const std::vector<Vec3> expected{{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {6, 0, 0}, {8, 0, 0}, {8, 2, 0}, {8, 4, 0}, {8, 6, 0}};
    REQUIRE(padded == expected);
}

TEST_CASE("Algorithm 2 keeps the originals in order and adds points on their segments", "[animation][addpoint]")
{
    const std::vector<Vec3> original{{0, 0, 0}, {1, 3, 0}, {4, 3, 2}, {6, -1, 1}, {7, 0, 0}};
    for (std::size_t target = 5; target <= 40; ++target) {
        const std::vector<Vec3> padded = add_points(original, target);
        CAPTURE(target);
        REQUIRE(padded.size() == target);
        require_refines(original, padded);
    }
    REQUIRE(add_points(original, 3) == original);
}

TEST_CASE("a single point is repeated to the count", "[animation][addpoint]")
{
    const std::vector<Vec3> one{{1, 2, 3}};
    REQUIRE(add_points(one, 3) == std::vector<Vec3>(3, Vec3{1, 2, 3}));
}

TEST_CASE("Algorithm 1 plans A parts into B pieces and the rest into C, A·B + (N2−A)·C = N1", "[animation][addpoint]")
{
    for (std::size_t larger = 1; larger <= 30; ++larger) {
        for (std::size_t smaller = 1; smaller <= larger; ++smaller) {
            const PartSplitPlan plan = plan_part_split(larger, smaller);
            REQUIRE(plan.split_more * plan.more_pieces + (smaller - plan.split_more) * plan.fewer_pieces == larger);
        }
    }
    // N1 = 7, N2 = 3: A = 1, B = 3, C = 2.
    const PartSplitPlan plan = plan_part_split(7, 3);
    REQUIRE(plan.split_more == 1);
    REQUIRE(plan.more_pieces == 3);
    REQUIRE(plan.fewer_pieces == 2);
}

TEST_CASE("splitting a part keeps the order and shares the cut points", "[animation][addpoint]")
{
    const GraphicPart part = part_of({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}, "arm");
    const auto pieces = split_part(part, 3);
    REQUIRE(pieces.size() == 3);
    REQUIRE(pieces[0].name == "arm.1");
    REQUIRE(pieces[0].points == std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
    REQUIRE(pieces[1].points == std::vector<Vec3>{{1, 0, 0}, {2, 0, 0}});
    REQUIRE(pieces[2].points == std::vector<Vec3>{{2, 0, 0}, {3, 0, 0}, {4, 0, 0}});
}

TEST_CASE("a part with too few points gets points before it is split", "[animation][addpoint]")
{
    const auto pieces = split_part(part_of({{0, 0, 0}, {6, 0, 0}}), 3);
    REQUIRE(pieces.size() == 3);
    REQUIRE(pieces[0].points == std::vector<Vec3>{{0, 0, 0}, {2, 0, 0}});
    REQUIRE(pieces[2].points == std::vector<Vec3>{{4, 0, 0}, {6, 0, 0}});
}

TEST_CASE("equalised keys have equal parts and point counts whichever key is larger", "[animation][addpoint]")
{
    Graphic many;
    many.parts = {part_of({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}}, "a"), part_of({{3, 0, 0}, {4, 4, 0}}, "b"),
                  part_of({{5, 0, 0}, {6, 1, 0}, {7, 2, 0}, {8, 0, 0}}, "c"), part_of({{9, 9, 0}, {9, 8, 0}}, "d")};
    Graphic few;
    few.parts = {part_of({{0, 5, 0}, {5, 5, 0}, {9, 5, 0}}, "x")};
    for (const bool swap : {false, true}) {
        const EqualisedKeys keys = swap ? equalise_key_frames(few, many) : equalise_key_frames(many, few);
        REQUIRE(keys.key1.parts.size() == 4);
        REQUIRE(keys.key2.parts.size() == 4);
        for (std::size_t i = 0; i < 4; ++i)
            REQUIRE(keys.key1.parts[i].points.size() == keys.key2.parts[i].points.size());
        const Graphic& original_many = many;
        const Graphic& padded_many = swap ? keys.key2 : keys.key1;
        for (std::size_t i = 0; i < 4; ++i)
            require_refines(original_many.parts[i].points, padded_many.parts[i].points);
        const Graphic& padded_few = swap ? keys.key1 : keys.key2;
        require_refines(few.parts[0].points, padded_few.all_points());
    }
}

TEST_CASE("keys that already match are left as they are", "[animation][addpoint]")
{
    Graphic key;
    key.parts = {part_of({{0, 0, 0}, {1, 1, 1}})};
    const EqualisedKeys keys = equalise_key_frames(key, key);
    REQUIRE(keys.key1.all_points() == key.all_points());
    REQUIRE(keys.key2.all_points() == key.all_points());
}
