#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include "apcs/cli/play_command.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

using namespace apcs;
using apcs::test::run_apcs;

namespace {

const std::filesystem::path data_folder = std::filesystem::path(APCS_SOURCE_DIR) / "data";

const char* const example_scenes[] = {"robot/robot.scn", "bicycle/bicycle.scn", "car/car.scn",
                                      "snake-apple/snake-apple.scn"};

} // namespace

TEST_CASE("every joint of every example holds within its tolerance in every frame", "[scene][examples]")
{
    for (const char* name : example_scenes) {
        CAPTURE(name);
        const Expected<Scene> scene = read_scene_file(data_folder / name, {});
        INFO((scene ? std::string() : scene.error().to_string()));
        REQUIRE(scene.has_value());
        PathSettings settings;
        settings.spacing = Spacing::exact;
        const SceneAnimation animation(*scene, settings);
        const double tolerance = default_joint_tolerance(*scene);
        std::size_t checked = 0;
        for (int f = 0; f <= scene->last_frame; ++f) {
            const std::vector<Vec3> points = animation.frame(f);
            for (std::size_t i = 0; i < scene->objects.size(); ++i) {
                const SceneObject& object = scene->objects[i];
                if (!object.parent)
                    continue;
                for (const SceneJoint& joint : object.joints)
                    for (const SceneJoint& partner : scene->objects[*object.parent].joints)
                        if (partner.name == joint.name) {
                            const Vec3 mine = points[animation.object_points()[i].first + joint.point];
                            const Vec3 theirs = points[animation.object_points()[*object.parent].first + partner.point];
                            REQUIRE(distance(mine, theirs) <= tolerance);
                            ++checked;
                        }
            }
        }
        if (std::string(name).starts_with("robot"))
            REQUIRE(checked == 13u * 13u); // 13 joints x frames 0 ... 12
    }
}

TEST_CASE("apcs play prints, writes and draws a scene; without a terminal it says what to give", "[scene][cli]")
{
    const std::string car = (data_folder / "car/car.scn").string();
    const auto printed = run_apcs({"play", car, "--print"});
    REQUIRE(printed.status == 0);
    REQUIRE(printed.out.starts_with("# frame 0\n# object road\n"));
    REQUIRE(printed.out.find("# frame 60\n# object road\n") != std::string::npos);
    REQUIRE(printed.out.find("# frame 61\n") == std::string::npos);
    REQUIRE(run_apcs({"play", car, "--print"}).out == printed.out); // deterministic

    apcs::test::TempFolder folder;
    const auto written = run_apcs({"play", car, "--out", folder.path().string(), "--png",
                                   (folder.path() / "car.png").string()});
    REQUIRE(written.status == 0);
    REQUIRE(std::filesystem::exists(folder.path() / "frm000.dat"));
    REQUIRE(std::filesystem::exists(folder.path() / "frm060.dat"));
    REQUIRE_FALSE(std::filesystem::exists(folder.path() / "frm061.dat"));
    REQUIRE(std::filesystem::file_size(folder.path() / "car.png") > 1000);
    std::ifstream frame(folder.path() / "frm010.dat");
    const std::string text((std::istreambuf_iterator<char>(frame)), std::istreambuf_iterator<char>());
    REQUIRE(text.find("PART road/P1 OPEN\n") != std::string::npos);
    REQUIRE(text.find("PART car/body CLOSED\n") != std::string::npos);

    const auto no_terminal = run_apcs({"play", car});
    REQUIRE(no_terminal.status == 3);
    REQUIRE(no_terminal.err ==
            "apcs: standard input is not a terminal; give --print, --out, --png, --svg or --gif to play a scene without "
            "one\n");
    const auto missing = run_apcs({"play", (folder.path() / "none.scn").string(), "--print"});
    REQUIRE(missing.status == 1);
    REQUIRE(missing.out.empty());
}

TEST_CASE("the frame files are numbered as wide as the last frame needs, at least three digits", "[scene]")
{
    REQUIRE(scene_frame_file_name(0, 60) == "frm000.dat");
    REQUIRE(scene_frame_file_name(7, 999) == "frm007.dat");
    REQUIRE(scene_frame_file_name(7, 1000) == "frm0007.dat");
    REQUIRE(scene_frame_file_name(100000, 100000) == "frm100000.dat");
}

TEST_CASE("apcs play --tree prints the robot as fig. 3.3.2's data structure", "[scene][examples]")
{
    const auto tree = run_apcs({"play", (data_folder / "robot/robot.scn").string(), "--tree"});
    REQUIRE(tree.status == 0);
    REQUIRE(tree.out.starts_with("robot.scn: frames 0-12, 15 objects\n`-- robot  t c b a +0.00 +0.00 +0.00 +0.00  N=1  MOVE\n"));
    const auto tree_and_print = run_apcs({"play", (data_folder / "robot/robot.scn").string(), "--tree", "--print"});
    REQUIRE(tree_and_print.status == 2);
    REQUIRE(tree_and_print.out.empty());
    for (const char* part : {"head", "torso", "arm-l", "palm-l", "fingers-l", "thigh-r", "calf-r", "sole-r"})
        REQUIRE(tree.out.find(std::string("-- ") + part + "  ") != std::string::npos);
}
