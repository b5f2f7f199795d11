#include "scene_test_support.h"

#include "apcs/scene/scene_joints.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;

TEST_CASE("a joint is found by name with its part's point and its parent's", "[scene][joints]")
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
    CHECK(neck->part == 1);
    CHECK(neck->part_point == 1); // JOINT neck 2 in head: its second point
    CHECK(neck->parent == 0);
    CHECK(neck->parent_point == 2);
    CHECK_FALSE(find_joint(scene, "knee").has_value());
    CHECK_FALSE(find_joint(scene, "NECK").has_value());
}

TEST_CASE("the robot's key points A and B are the thesis' neck and wrist", "[scene][joints][examples]")
{
    const Expected<Scene> robot =
        read_scene_file(std::filesystem::path(APCS_SOURCE_DIR) / "data/robot/robot.scn", {});
    REQUIRE(robot.has_value());
    const std::optional<JointEnds> neck = find_joint(*robot, "neck");
    REQUIRE(neck.has_value());
    CHECK(robot->objects[neck->parent].name == "torso");
    CHECK(neck->parent_point == 6);
    CHECK(robot->objects[neck->part].name == "head");
    CHECK(neck->part_point == 0);
    const std::optional<JointEnds> wrist = find_joint(*robot, "wrist-r");
    REQUIRE(wrist.has_value());
    CHECK(robot->objects[wrist->parent].name == "arm-r");
    CHECK(wrist->parent_point == 1);
    CHECK(robot->objects[wrist->part].name == "palm-r");
    CHECK(wrist->part_point == 0);
}
