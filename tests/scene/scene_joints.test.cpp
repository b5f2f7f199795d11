#include "scene_test_support.h"

#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_joints.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;

TEST_CASE("a joint is found by name with its two ends, the part declared first first", "[scene][joints]")
{
    test::DatFiles files;
    files.texts["body.dat"] = "0 0 0\n1 0 0\n1 1 0\n";
    files.texts["head.dat"] = "5 5 5\n1 1 0\n";
    const Scene scene = test::scene_from("FRAMES 2\n"
                                         "OBJECT body\nSHAPE body.dat\nJOINT neck 3\n"
                                         "OBJECT head PARENT body\nSHAPE head.dat\nJOINT neck 2\n",
                                         files);
    const std::optional<JointEnds> neck = find_joint(scene, "neck");
    REQUIRE(neck.has_value());
    CHECK(neck->earlier.object == 0);
    CHECK(neck->earlier.first == 2); // JOINT neck 3 in body: its third point
    CHECK(neck->later.object == 1);
    CHECK(neck->later.first == 1);
    CHECK_FALSE(find_joint(scene, "knee").has_value());
    CHECK_FALSE(find_joint(scene, "NECK").has_value());
}

TEST_CASE("joints form a graph of their own: two parts in different branches join, each part anchored at its "
          "first joint with a part declared before it",
          "[scene][joints]")
{
    test::DatFiles files;
    files.texts["a.dat"] = "0 0 0\n0 1 0\n";
    files.texts["b.dat"] = "0 1 0\n0 2 0\n";
    files.texts["c.dat"] = "0 2 0\n0 3 0\n";
    // b and c sit in different groups; c names its joint with a part declared after it first.
    const Scene scene = test::scene_from("FRAMES 2\nOBJECT body\n"
                                         "OBJECT left PARENT body\nOBJECT a PARENT left\nSHAPE a.dat\nJOINT ab 2\n"
                                         "OBJECT right PARENT body\nOBJECT b PARENT right\nSHAPE b.dat\nJOINT ab 1\nJOINT bc 2\n"
                                         "OBJECT c PARENT left\nSHAPE c.dat\nJOINT cd 2\nJOINT bc 1\n"
                                         "OBJECT d PARENT left\nSHAPE c.dat\nJOINT cd 2\n",
                                         files);
    // Objects: body 0, left 1, a 2, right 3, b 4, c 5, d 6.
    REQUIRE_FALSE(scene.objects[2].anchor.has_value()); // a: nothing before it to join
    REQUIRE(scene.objects[4].anchor.has_value());
    CHECK(scene.objects[4].anchor->partner == 2); // b on a, across the branches
    CHECK(scene.objects[4].anchor->joint == 0);
    REQUIRE(scene.objects[5].anchor.has_value());
    CHECK(scene.objects[5].anchor->partner == 4); // c on b by its second JOINT line: d comes later
    CHECK(scene.objects[5].anchor->joint == 1);
    CHECK(scene.objects[5].anchor->partner_joint == 1);
    REQUIRE(scene.objects[6].anchor.has_value());
    CHECK(scene.objects[6].anchor->partner == 5);
    CHECK(root_object(scene, 6) == 0);
}

TEST_CASE("the robot's key points A and B are the thesis' neck and wrist", "[scene][joints][examples]")
{
    const Expected<Scene> robot =
        read_scene_file(std::filesystem::path(APCS_SOURCE_DIR) / "data/robot/robot.scn", {});
    REQUIRE(robot.has_value());
    const std::optional<JointEnds> neck = find_joint(*robot, "neck");
    REQUIRE(neck.has_value());
    CHECK(robot->objects[neck->earlier.object].name == "head");
    CHECK(neck->earlier.first == 0);
    CHECK(robot->objects[neck->later.object].name == "torso");
    CHECK(neck->later.first == 6);
    const std::optional<JointEnds> wrist = find_joint(*robot, "wrist-r");
    REQUIRE(wrist.has_value());
    CHECK(robot->objects[wrist->earlier.object].name == "arm-r");
    CHECK(wrist->earlier.first == 1);
    CHECK(robot->objects[wrist->later.object].name == "palm-r");
    CHECK(wrist->later.first == 0);
}

TEST_CASE("a joint drawn exactly TOLERANCE apart is accepted, round-off not deciding", "[scene][joints]")
{
    // Issue 45: 0.4 - 0.1 is 0.30000000000000004 in doubles, and TOLERANCE 0.3 refused it.
    test::DatFiles files;
    files.texts["a.dat"] = "0 0 0\n0 0.1 0\n";
    files.texts["b.dat"] = "0 0.4 0\n0 1 0\n";
    files.texts["c.dat"] = "0 0.40001 0\n0 1 0\n";
    files.texts["far-a.dat"] = "0 0 0\n0 100000000.1 0\n";
    files.texts["far-b.dat"] = "0 100000000.4 0\n0 100000001 0\n";
    const auto joined = [&files](const std::string& first, const std::string& second) {
        return parse_scene("FRAMES 2\nOBJECT a\nSHAPE " + first + "\nJOINT j 2 TOLERANCE 0.3\nOBJECT b PARENT a\nSHAPE " +
                               second + "\nJOINT j 1\n",
                           "t.scn", files.reader(), {});
    };
    const Expected<Scene> exact = joined("a.dat", "b.dat");
    REQUIRE(exact.has_value());
    // Nor does round-off move the part onto its partner: frame 0 shows it as drawn.
    const SceneAnimation animation(*exact, {});
    CHECK(animation.frame(0)[2] == Vec3{0, 0.4, 0});
    // Far from the origin the round-off is larger, and so is what is forgiven.
    CHECK(joined("far-a.dat", "far-b.dat").has_value());
    const Expected<Scene> apart = joined("a.dat", "c.dat");
    REQUIRE_FALSE(apart.has_value());
    CHECK(apart.error().to_string() == "t.scn:7: joint 'j': point 2 of 'a' (line 4) (0, 0.1, 0) and point 1 of 'b' "
                                       "(0, 0.40001, 0) are 0.30001 apart in frame 0; expected at most 0.3");
}
