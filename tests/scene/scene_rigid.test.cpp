#include "scene/scene_test_support.h"

#include "apcs/scene/rigid_turn.h"
#include "apcs/scene/scene_animation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace apcs;
using apcs::test::DatFiles;
using apcs::test::scene_from;

namespace {

bool near(const Vec3& a, const Vec3& b, double within = 1e-9) { return distance(a, b) <= within; }

// A limb 2 long hanging from point 2 of a base at (0, 1, 0) in KEY1, pointing along +y in KEY2
// (drawn elsewhere: only its turn counts), a quarter turn about +x; a hand hangs at its tip.
DatFiles limb_files()
{
    DatFiles files;
    files.texts["base.dat"] = "0 0 0\n0 1 0\n";
    files.texts["limb1.dat"] = "0 1 0\n0 1 -2\n";
    files.texts["limb2.dat"] = "0 5 5\n0 7 5\n";
    files.texts["hand.dat"] = "0 1 -2\n0 1.5 -2\n";
    files.texts["up.dat"] = "0 0 0\n0 0 4\n";
    return files;
}

std::string limb_scene(const std::string& staff, const std::string& base_move = "")
{
    return "FRAMES 4\nOBJECT base\n" + staff + "SHAPE base.dat\n" + base_move + "JOINT hip 2\n" +
           "OBJECT limb PARENT base\nKEYS limb1.dat limb2.dat\nRIGID\nJOINT hip 1\nJOINT wrist 2\n"
           "OBJECT hand PARENT base\nSHAPE hand.dat\nJOINT wrist 1\n";
}

// The limb's tip turned `degrees` about +x from straight down, about the hip at `hip`.
Vec3 tip_at(double degrees, const Vec3& hip)
{
    const double radians = degrees * std::numbers::pi / 180.0;
    return hip + Vec3{0, 2 * std::sin(radians), -2 * std::cos(radians)};
}

} // namespace

TEST_CASE("Kabsch's turn carries a drawing onto its turned copy, and a mirror image is no turn", "[scene][rigid]")
{
    const std::vector<Vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 2, 0.5}};
    // A third of a turn about (1, 1, 1) maps x -> y -> z -> x; then moved by (3, -1, 2).
    std::vector<Vec3> turned;
    for (const Vec3& p : triangle)
        turned.push_back(Vec3{p.z, p.x, p.y} + Vec3{3, -1, 2});
    const RigidTurn turn = fit_rigid_turn(triangle, turned);
    CHECK(turn.worst_deviation < 1e-12);
    const double half = 0.5; // cos(60°), and sin(60°)/√3 on each axis
    CHECK(turn.quaternion[0] == Approx(half).margin(1e-12));
    for (std::size_t axis = 1; axis < 4; ++axis)
        CHECK(turn.quaternion[axis] == Approx(half).margin(1e-12));
    CHECK(turn.size == Approx(std::sqrt(1 + 4 + 0.25)));

    // A flat drawing's mirror image is the drawing turned over; a solid's is not.
    const std::vector<Vec3> solid{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
    std::vector<Vec3> mirrored;
    for (const Vec3& p : solid)
        mirrored.push_back({p.x, -p.y, p.z});
    CHECK(fit_rigid_turn(solid, mirrored).worst_deviation > 0.3);
}

TEST_CASE("a drawing on one line turns by the smallest rotation between its directions, not rolling about itself",
          "[scene][rigid]")
{
    const std::vector<Vec3> down{{0, 0, 0}, {0, 0, -1}, {0, 0, -2}};
    const std::vector<Vec3> ahead{{0, 5, 5}, {0, 6, 5}, {0, 7, 5}};
    const RigidTurn turn = fit_rigid_turn(down, ahead);
    CHECK(turn.worst_deviation < 1e-12);
    const Affine half = partial_turn(turn, 0.5, Vec3{});
    // Half of the quarter turn about +x: the far end at 45 degrees, still in the plane x = 0.
    CHECK(near(half(Vec3{0, 0, -2}), tip_at(45, Vec3{})));
}

TEST_CASE("a RIGID limb turns about its anchor by the staff's law and keeps its length, and a part anchored to it "
          "follows",
          "[scene][rigid]")
{
    const DatFiles files = limb_files();
    const Vec3 hip{0, 1, 0};
    SECTION("acceleration 0: equal angles")
    {
        const Scene scene = scene_from(limb_scene(""), files);
        const SceneAnimation animation(scene, {});
        for (int f = 0; f <= 4; ++f) {
            const std::vector<Vec3> points = animation.frame(f); // base 0-1, limb 2-3, hand 4-5
            CAPTURE(f);
            CHECK(near(points[2], hip));
            CHECK(near(points[3], tip_at(90.0 * f / 4, hip)));
            CHECK(near(points[4], points[3]));               // the hand on the wrist
            CHECK(near(points[5], points[3] + Vec3{0, 0.5, 0})); // moved, not turned
        }
    }
    SECTION("acceleration +1: the fraction 1 - cos(pi tau / 2) of the turn (SPEC 4.3)")
    {
        const Scene scene = scene_from(limb_scene("STAFF 0 0 0 1\n"), files);
        const SceneAnimation animation(scene, {});
        const double fraction = 1 - std::cos(std::numbers::pi / 4); // tau = 2/4
        CHECK(near(animation.frame(2)[3], tip_at(90.0 * fraction, hip)));
        CHECK(near(animation.frame(4)[3], tip_at(90.0, hip)));
    }
    SECTION("the anchor's part moving: the limb rides on it")
    {
        const Scene scene = scene_from(limb_scene("", "MOVE up.dat\n"), files);
        const SceneAnimation animation(scene, {});
        const std::vector<Vec3> points = animation.frame(2);
        CHECK(near(points[2], hip + Vec3{0, 0, 2}));
        CHECK(near(points[3], tip_at(45, hip + Vec3{0, 0, 2})));
    }
}

TEST_CASE("a drawing on one line whose first and last points meet turns like any other line", "[scene][rigid]")
{
    // Out and back along -z (a closed stroke), turned a quarter to +y: congruent, not refused.
    const std::vector<Vec3> down{{0, 0, 0}, {0, 0, -1}, {0, 0, 0}};
    const std::vector<Vec3> ahead{{0, 5, 5}, {0, 6, 5}, {0, 5, 5}};
    const RigidTurn turn = fit_rigid_turn(down, ahead);
    CHECK(turn.worst_deviation < 1e-12);
    CHECK(near(partial_turn(turn, 0.5, Vec3{})(Vec3{0, 0, -2}), tip_at(45, Vec3{})));
}

TEST_CASE("a drawing on one line turned half round turns about the face-on axis x when its line is across it",
          "[scene][rigid]")
{
    // Along +y, then along -y: no smallest rotation; x keeps it in the thesis' face-on plane.
    const std::vector<Vec3> ahead{{0, 0, 0}, {0, 1, 0}, {0, 2, 0}};
    const std::vector<Vec3> behind{{0, 0, 0}, {0, -1, 0}, {0, -2, 0}};
    const RigidTurn turn = fit_rigid_turn(ahead, behind);
    CHECK(turn.worst_deviation < 1e-12);
    const Vec3 half = partial_turn(turn, 0.5, Vec3{})(Vec3{0, 2, 0});
    CHECK(std::abs(half.x) < 1e-12);
    CHECK(std::abs(std::abs(half.z) - 2) < 1e-12);
    // Along x (a top view's line): about y, the first axis across it.
    const std::vector<Vec3> east{{0, 0, 0}, {1, 0, 0}};
    const std::vector<Vec3> west{{0, 0, 0}, {-1, 0, 0}};
    const Vec3 quarter = partial_turn(fit_rigid_turn(east, west), 0.5, Vec3{})(Vec3{1, 0, 0});
    CHECK(std::abs(quarter.y) < 1e-12);
    CHECK(std::abs(std::abs(quarter.z) - 1) < 1e-12);
}

TEST_CASE("a RIGID part whose turn takes it past 1e9 between its keys is out of reach", "[scene][rigid]")
{
    // A limb 1.8e9 long from (0, 9e8, 0) pointing along -y in KEY1 and +z in KEY2: both keys within
    // 1e9, but half way through the quarter turn its tip is at z = 1.27e9 (frame 2 of 4).
    DatFiles files;
    files.texts["base.dat"] = "0 0 0\n0 900000000 0\n";
    files.texts["limb1.dat"] = "0 900000000 0\n0 -900000000 0\n";
    files.texts["limb2.dat"] = "0 0 -900000000\n0 0 900000000\n";
    const Scene scene = scene_from("FRAMES 4\nOBJECT base\nSHAPE base.dat\nJOINT hip 2\n"
                                   "OBJECT limb PARENT base\nKEYS limb1.dat limb2.dat\nRIGID\nJOINT hip 1\n",
                                   files);
    const SceneAnimation animation(scene, {});
    const std::optional<OutOfReach> beyond = animation.first_out_of_reach(1e9);
    REQUIRE(beyond.has_value());
    CHECK(beyond->object == 1);
    CHECK(beyond->frame == 2); // frame 1, a quarter of the way: |y| 7.6e8, z 6.9e8
    CHECK(beyond->magnitude == Approx(1.8e9 * std::sin(std::numbers::pi / 4)));
}

TEST_CASE("a RIGID part of no size is not refused over round-off, and a part that is not congruent still is",
          "[scene][rigid]")
{
    // Issue 45: every point of each key at one place, KEY2 elsewhere: congruent (a dot moved), but
    // the centroid's round-off (1e-16) was above 1e-4 of its size, 0, and the part was refused.
    DatFiles files;
    files.texts["base.dat"] = "0 0 0\n0.1 0.2 0.3\n";
    files.texts["dot1.dat"] = "0.1 0.2 0.3\n0.1 0.2 0.3\n0.1 0.2 0.3\n";
    files.texts["dot2.dat"] = "0.7 1.3 2.9\n0.7 1.3 2.9\n0.7 1.3 2.9\n";
    files.texts["spread.dat"] = "0.7 1.3 2.9\n0.7 1.3 2.9\n0.7 1.3 3\n";
    const std::string head = "FRAMES 2\nOBJECT base\nSHAPE base.dat\nJOINT j 2\nOBJECT dot PARENT base\n";
    const Expected<Scene> dot =
        parse_scene(head + "KEYS dot1.dat dot2.dat\nRIGID\nJOINT j 1\n", "t.scn", files.reader(), {});
    INFO((dot ? std::string() : dot.error().to_string()));
    REQUIRE(dot.has_value());
    const SceneAnimation animation(*dot, {});
    for (int f = 0; f <= 2; ++f) {
        const std::vector<Vec3> points = animation.frame(f); // base 0-1, the dot 2-4 on the joint
        for (std::size_t p = 2; p < 5; ++p)
            CHECK(near(points[p], Vec3{0.1, 0.2, 0.3}));
    }
    const Expected<Scene> spread =
        parse_scene(head + "KEYS dot1.dat spread.dat\nRIGID\nJOINT j 1\n", "t.scn", files.reader(), {});
    REQUIRE_FALSE(spread.has_value());
    CHECK(spread.error().to_string().starts_with(
        "t.scn:7: RIGID part 'dot': its KEY2 drawing is not its KEY1 drawing turned and moved: point 3 is 0.0666667 "
        "off"));
}
