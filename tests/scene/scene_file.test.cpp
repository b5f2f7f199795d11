#include "scene/scene_test_support.h"

#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_tree.h"

#include <catch2/catch.hpp>

using namespace apcs;
using apcs::test::DatFiles;
using apcs::test::scene_from;

namespace {

DatFiles example_files()
{
    DatFiles files;
    files.texts["square.dat"] = "PART sq CLOSED\n0 0 0\n0 1 0\n0 1 1\n0 0 1\n";
    files.texts["stick.dat"] = "0 0 1\n0 0 2\n";
    files.texts["path.dat"] = "0 0 0\n0 5 0\n0 10 0\n";
    files.texts["path7.dat"] = "0 0 0 0 0 0 0.5\n0 5 0 0 0 0 0\n";
    files.texts["k1.dat"] = "0 0 0\n0 1 0\n";
    files.texts["k2.dat"] = "0 0 2\n0 1 2\n0 2 2\n";
    files.texts["turned.dat"] = "0 0 0\n0 0 1\n"; // k1.dat turned a quarter about x
    files.texts["near.dat"] = "0 0.3 0\n0 1 0\n";
    files.texts["far.dat"] = "0 11.6 0\n0 12 0\n"; // 11.6 - 0.3 is 11.299999999999999 in doubles
    files.texts["tiny.dat"] = "0 0 0\n0 1e-300 0\n";
    return files;
}

} // namespace

TEST_CASE("a scene file gives its objects, parents, drawings and behaviours", "[scene]")
{
    const Scene scene = scene_from("; a comment\r\nFRAMES 20\r\nview 0 90\r\n"
                                   "OBJECT body\nSHAPE square.dat\nMOVE path.dat FROM 2 TO 12 LOOP\n"
                                   "staff 0.5 0 0 0\n"
                                   "object arm parent body\nshape stick.dat\nROTATE 15 AXIS z ABOUT 1 2 3 TO 4\n"
                                   "SCALE 2 FROM 1 TO 3\n\x1a",
                                   example_files());
    REQUIRE(scene.last_frame == 20);
    REQUIRE(scene.view->theta_degrees == 0.0);
    REQUIRE(scene.objects.size() == 2);
    const SceneObject& body = scene.objects[0];
    REQUIRE(body.shape->point_count() == 4);
    REQUIRE(body.move->frames.from == 2);
    REQUIRE(body.move->frames.to == 12);
    REQUIRE(body.move->loop);
    // The body's STAFF came after its MOVE: the three-column path still takes it.
    REQUIRE(body.move->path[1].staff.tension == 0.5);
    const SceneObject& arm = scene.objects[1];
    REQUIRE(arm.parent == 0u);
    REQUIRE(arm.staff.tension == 0.5); // inherited from its parent (Ch. 3.3)
    REQUIRE_FALSE(arm.own_staff);
    REQUIRE(arm.rotate->axis == Axis::z);
    REQUIRE(arm.rotate->about == Vec3{1, 2, 3});
    REQUIRE(arm.rotate->frames.from == 0);
    REQUIRE(arm.rotate->frames.to == 4);
    REQUIRE(arm.scale->factors == Vec3{2.0, 2.0, 2.0});
    REQUIRE(arm.scale->frames.to == 3);
}

TEST_CASE("a scene's SPACING line, in any case, gives its spacing — without one it plays nearest, as every command",
          "[scene][spacing]")
{
    const DatFiles files = example_files();
    const std::string objects = "OBJECT a\nSHAPE square.dat\nMOVE path.dat\n";
    const Scene plain = scene_from("FRAMES 10\n" + objects, files);
    REQUIRE_FALSE(plain.spacing.has_value());
    const Scene exact = scene_from("FRAMES 10\nVIEW 0 90\nSpacing Exact\n" + objects, files);
    REQUIRE(exact.spacing == Spacing::exact);
    const Scene nearest = scene_from("FRAMES 10\nSPACING nearest ; the thesis' samples\n" + objects, files);
    REQUIRE(nearest.spacing == Spacing::nearest);
    // The settings the scene plays with: its line's spacing, exact without one (SPEC 8.1, turn 5),
    // unless --spacing was given.
    PathSettings command;
    command.samples_per_segment = 8;
    command.spacing = Spacing::nearest; // the commands' default, not the scene's
    REQUIRE(scene_path_settings(plain, command, false).spacing == Spacing::exact);
    REQUIRE(scene_path_settings(plain, command, false).samples_per_segment == 8);
    REQUIRE(scene_path_settings(exact, {}, false).spacing == Spacing::exact);
    REQUIRE(scene_path_settings(nearest, command, false).spacing == Spacing::nearest);
    REQUIRE(scene_path_settings(exact, command, true).spacing == Spacing::nearest);
    command.spacing = Spacing::exact;
    REQUIRE(scene_path_settings(nearest, command, true).spacing == Spacing::exact);
}

TEST_CASE("a part's own STAFF replaces its parent's — seven-column paths keep their own values", "[scene]")
{
    const Scene scene = scene_from("FRAMES 10\nOBJECT a\nSTAFF 0.5 0.5 0.5 0.5\nOBJECT b PARENT a\n"
                                   "STAFF -0.25 0 0 0\nMOVE path.dat\nOBJECT c PARENT a\nMOVE path7.dat\n",
                                   example_files(), StaffValues{0.1, 0.1, 0.1, 0.1});
    REQUIRE(scene.objects[0].staff.tension == 0.5);
    REQUIRE(scene.objects[1].move->path[0].staff == StaffValues{-0.25, 0, 0, 0});
    REQUIRE(scene.objects[2].move->path[0].staff == StaffValues{0, 0, 0, 0.5});
    const Scene defaults = scene_from("FRAMES 10\nOBJECT a\nMOVE path.dat\n", example_files(), StaffValues{0.1, 0, 0, 0});
    REQUIRE(defaults.objects[0].move->path[0].staff.tension == 0.1);
}

TEST_CASE("KEYS equalise the key frames, and their paths default to straight lines", "[scene]")
{
    const Scene scene = scene_from("FRAMES 10\nOBJECT a\nKEYS k1.dat k2.dat FROM 2 TO 8\n", example_files());
    const SceneKeys& keys = *scene.objects[0].keys;
    REQUIRE(keys.keys.key1.point_count() == 3); // points added to KEY1 (SPEC 5.1)
    REQUIRE(keys.frames.from == 2);
    REQUIRE(keys.frames.to == 8);
    REQUIRE(keys.first_path.size() == 2);
    REQUIRE(keys.first_path[1].position == Vec3{0, 0, 2});
    REQUIRE(keys.last_path[1].position == Vec3{0, 2, 2});
}

TEST_CASE("each malformed scene is refused with its file and line", "[scene]")
{
    struct Row {
        std::string text;
        std::string message;
    };
    const std::string head = "FRAMES 10\nOBJECT a\nSHAPE square.dat\n";
    const std::string joints = head + "JOINT j 1\nOBJECT b PARENT a\nSHAPE square.dat\n";
    const std::string joined = joints + "JOINT j 1\n";
    const Row rows[] = {
        {"OBJECT a\n", "t.scn:1: expected 'FRAMES N' as the first data line, found 'OBJECT'"},
        {"FRAMES 0\n", "t.scn:1: expected 'FRAMES N' with N a whole number from 1 to 100000"},
        {"FRAMES 100001\n", "t.scn:1: expected 'FRAMES N' with N a whole number from 1 to 100000"},
        {"FRAMES 5\n", "t.scn: expected at least one OBJECT line; the file has none"},
        // Issue 45: names and file names that would reach a terminal raw (--tree, --print, frames).
        {"FRAMES 10\nOBJECT a\x1b]0;title\x07\n",
         "t.scn:2: expected printable text; found the control character \\x1B (a terminal would obey it)"},
        {head + "OBJECT b\x1b[?1049h\n",
         "t.scn:4: expected printable text; found the control character \\x1B (a terminal would obey it)"},
        {"FRAMES 10\nOBJECT a\nSHAPE sq\xc2\x9b" "2J.dat\n",
         "t.scn:3: expected printable text; found the control character U+009B (a terminal would obey it)"},
        {"FRAMES 10\nOBJECT a\x7f\n",
         "t.scn:2: expected printable text; found the control character \\x7F (a terminal would obey it)"},
        // Issue 33: the last TOLERANCE of a joint silently won.
        {head + "JOINT j 1 TOLERANCE 0.5\nOBJECT b PARENT a\nSHAPE square.dat\nJOINT j 1 TOLERANCE 0.25\n",
         "t.scn:7: joint 'j' has TOLERANCE 0.25 here and 0.5 on line 4; expected one value (or the same on both lines)"},
        {"FRAMES 5\nSHAPE square.dat\n", "t.scn:2: SHAPE before the first OBJECT line; expected 'OBJECT NAME' first"},
        {head + "WIGGLE 3\n",
         "t.scn:4: unknown keyword 'WIGGLE'; expected OBJECT, SHAPE, KEYS, PATHS, STAFF, MOVE, ROTATE, ROLL, SCALE, JOINT, RIGID, "
         "VIEW or SPACING"},
        {head + "OBJECT a\n", "t.scn:4: object 'a' is declared again; its first OBJECT line is line 2 (names are unique)"},
        {head + "OBJECT b PARENT c\nOBJECT c\n",
         "t.scn:4: parent 'c' is not an object declared above; a parent is declared before its parts"},
        {head + "OBJECT b PARENT b\n",
         "t.scn:4: parent 'b' is not an object declared above; a parent is declared before its parts"},
        {head + "SHAPE square.dat\n", "t.scn:4: a second SHAPE or KEYS for object 'a'; expected one at most"},
        {head + "KEYS k1.dat k2.dat\n", "t.scn:4: a second SHAPE or KEYS for object 'a'; expected one at most"},
        {head + "ROTATE 1\nROTATE 2\n", "t.scn:5: a second ROTATE for object 'a'; expected one at most"},
        // Turn 4: ROLL RADIUS, one turn of its own (a ROTATE or a ROLL), no FROM/TO.
        {head + "ROLL\n", "t.scn:4: expected 'ROLL RADIUS [AXIS x|y|z] [ABOUT X Y Z]' with RADIUS the wheel's radius; "
                          "found nothing after ROLL"},
        {head + "ROLL AXIS x\n", "t.scn:4: expected 'ROLL RADIUS [AXIS x|y|z] [ABOUT X Y Z]' with RADIUS the wheel's "
                                 "radius, found 'AXIS'"},
        {head + "ROLL 0\n",
         "t.scn:4: ROLL RADIUS '0' is 0; expected the wheel's radius (above 0, or below 0 to roll the other way)"},
        {head + "ROLL -0.0\n",
         "t.scn:4: ROLL RADIUS '-0.0' is 0; expected the wheel's radius (above 0, or below 0 to roll the other way)"},
        {head + "ROLL 1e10\n", "t.scn:4: expected a number with |value| <= 1e9 for RADIUS, found '1e10'"},
        {head + "ROLL 1 FROM 2\n",
         "t.scn:4: unexpected 'FROM' in ROLL; expected its optional clauses (AXIS, ABOUT): it rolls whenever its hub moves"},
        {head + "ROLL 1 AXIS w\n", "t.scn:4: unknown AXIS 'w'; expected x, y or z"},
        {head + "ROLL 1\nROLL 2\n", "t.scn:5: a second ROLL for object 'a'; expected one at most"},
        {head + "ROTATE 1\nROLL 2\n", "t.scn:5: a second ROTATE or ROLL for object 'a'; expected one at most"},
        {head + "ROLL 1\nROTATE 2\n", "t.scn:5: a second ROTATE or ROLL for object 'a'; expected one at most"},
        {head + "MOVE path.dat\nMOVE path.dat\n", "t.scn:5: a second MOVE for object 'a'; expected one at most"},
        {head + "JOINT j 5\n", "t.scn:4: joint 'j' names point 5 of object 'a', whose drawing has 4 points"},
        {head + "JOINT j 1\n", "t.scn:4: joint 'j' is used 1 time(s); expected exactly twice, in two parts of one object"},
        {joints + "JOINT j 2\n",
         "t.scn:7: joint 'j': point 1 of 'a' (line 4) (0, 0, 0) and point 2 of 'b' (0, 1, 0) are 1 apart in frame 0; "
         "expected at most 0.00141421"},
        // Issue 45: messages printed 17-digit doubles (11.299999999999999); six digits, more only
        // where six would show two different values alike.
        {"FRAMES 10\nOBJECT a\nSHAPE near.dat\nJOINT j 1 TOLERANCE 4\nOBJECT b PARENT a\nSHAPE far.dat\nJOINT j 1\n",
         "t.scn:7: joint 'j': point 1 of 'a' (line 4) (0, 0.3, 0) and point 1 of 'b' (0, 11.6, 0) are 11.3 apart in "
         "frame 0; expected at most 4"},
        {head + "JOINT j 1 TOLERANCE 0.1234567\nOBJECT b PARENT a\nSHAPE square.dat\nJOINT j 1 TOLERANCE 0.1234568\n",
         "t.scn:7: joint 'j' has TOLERANCE 0.1234568 here and 0.1234567 on line 4; expected one value (or the same on "
         "both lines)"},
        {joined + "OBJECT c\nSHAPE square.dat\nJOINT k 1\nOBJECT d PARENT a\nSHAPE square.dat\nJOINT k 1\n",
         "t.scn:13: joint 'k' joins 'c' (line 10) of object 'c' and 'd' of object 'a'; expected two parts of one object"},
        {head + "RIGID\n", "t.scn:4: RIGID part 'a' has no KEYS; expected KEYS KEY1.dat KEY2.dat, the two poses it turns between"},
        {head + "RIGID yes\n", "t.scn:4: expected 'RIGID' alone on its line, found 'yes' after it"},
        {"FRAMES 10\nOBJECT a\nKEYS k1.dat turned.dat\nRIGID\nRIGID\n", "t.scn:5: a second RIGID for object 'a'; expected one at most"},
        {"FRAMES 10\nOBJECT a\nKEYS k1.dat turned.dat\nRIGID\n",
         "t.scn:4: RIGID part 'a' has no anchor: none of its joints is shared with a part declared before it; expected a "
         "JOINT with an earlier part (the joint it turns about)"},
        {"FRAMES 10\nOBJECT a\nKEYS k1.dat k2.dat\nRIGID\n",
         "t.scn:4: RIGID part 'a': its KEY2 drawing is not its KEY1 drawing turned and moved: point 1 is 0.5 off; expected "
         "within 1e-4 of its size (1)"},
        {head + "MOVE path.dat TIMES 0 5\n",
         "t.scn:4: TIMES gives 2 frames but 'path.dat' has 3 control points; expected one frame per control point"},
        {head + "MOVE path.dat TIMES 0 5 5\n",
         "t.scn:4: TIMES 5 after 5: expected increasing frames, one per control point"},
        {head + "MOVE path.dat TIMES 0 5 9 FROM 1\n",
         "t.scn:4: MOVE with both TIMES and FROM/TO; expected one of them (TIMES gives every control point's frame)"},
        {head + "MOVE path.dat FROM 6 TO 3\n", "t.scn:4: MOVE FROM 6 TO 3: expected FROM <= TO"},
        // Issue 45: TIMES without frames was a MOVE without TIMES; FROM 0 TO 0 moved frame 0.
        {head + "MOVE path.dat TIMES\n",
         "t.scn:4: TIMES without frames; expected one frame per control point of 'path.dat' (3)"},
        {head + "MOVE path.dat TIMES LOOP\n",
         "t.scn:4: TIMES without frames; expected one frame per control point of 'path.dat' (3)"},
        {head + "MOVE path.dat FROM 0 TO 0\n",
         "t.scn:4: MOVE FROM 0 TO 0 covers no frame: the object would jump to the path's end at frame 0; expected "
         "FROM before TO"},
        {head + "MOVE path.dat TO 0\n",
         "t.scn:4: MOVE FROM 0 TO 0 covers no frame: the object would jump to the path's end at frame 0; expected "
         "FROM before TO"},
        {head + "MOVE path.dat FROM 5 TO 5 LOOP\n",
         "t.scn:4: MOVE FROM 5 TO 5 covers no frame: the object would jump to the path's end at frame 5; expected "
         "FROM before TO"},
        // Issue 45: a path whose steps vanish in round-off gave NaN turns, blamed on the transforms.
        {head + "MOVE tiny.dat ALIGN AHEAD 1e-300\n",
         "t.scn:4: ALIGN on 'tiny.dat': its control points are all within 1e-300 of its first, too close for a "
         "direction; expected a path that spans more than 1e-150 and more than 1e-12 of its largest coordinate"},
        {head + "MOVE path.dat ALIGN AHEAD 1e-300\n",
         "t.scn:4: ALIGN AHEAD 1e-300 on 'path.dat': a chord that short is round-off, not a direction; expected D above "
         "1e-150 and above 1e-12 of the path's largest coordinate (10)"},
        {head + "MOVE tiny.dat ALIGN\n",
         "t.scn:4: ALIGN on 'tiny.dat': its control points are all within 1e-300 of its first, too close for a "
         "direction; expected a path that spans more than 1e-150 and more than 1e-12 of its largest coordinate"},
        {head + "ROTATE 5 FROM 11\n", "t.scn:4: expected a frame from 0 to 10 after FROM, found '11'"},
        {head + "ROTATE 5 AXIS w\n", "t.scn:4: unknown AXIS 'w'; expected x, y or z"},
        {head + "SCALE 0\n", "t.scn:4: SCALE FACTOR '0' is not above 0; expected a factor > 0"},
        {head + "JOINT j 3-2\n", "t.scn:4: joint points '3-2' run backwards; expected INDEX-INDEX2 with INDEX <= INDEX2"},
        {head + "JOINT j 2-x\n",
         "t.scn:4: expected the joint's point INDEX or points INDEX-INDEX2, whole numbers from 1 to 1000000, found '2-x'"},
        // Issue 33: a huge index was named as 18446744073709551615, not as written.
        {head + "JOINT j 18446744073709551617\n",
         "t.scn:4: expected the joint's point INDEX or points INDEX-INDEX2, whole numbers from 1 to 1000000, found "
         "'18446744073709551617'"},
        {head + "JOINT j 3-9\n", "t.scn:4: joint 'j' names point 9 of object 'a', whose drawing has 4 points"},
        {head + "SCALE 1 0 1\n", "t.scn:4: SCALE FACTOR '0' is not above 0; expected a factor > 0"},
        {head + "SCALE 1 1 1e9\n",
         "t.scn:4: SCALE '1e9' over 10 frames leaves 1e-6 ... 1e6; expected a factor nearer 1 or fewer frames (FROM/TO)"},
        {head + "SCALE 1 2\n", "t.scn:4: expected 'SCALE FACTOR' or 'SCALE FX FY FZ', one factor or three; found '2' after one"},
        {head + "SCALE 1 2 3 4\n",
         "t.scn:4: expected 'SCALE FACTOR' or 'SCALE FX FY FZ', one factor or three; found '4' after three"},
        {head + "SCALE -2\n", "t.scn:4: SCALE FACTOR '-2' is not above 0; expected a factor > 0"},
        {head + "SCALE 1e9\n",
         "t.scn:4: SCALE '1e9' over 10 frames leaves 1e-6 ... 1e6; expected a factor nearer 1 or fewer frames (FROM/TO)"},
        {head + "ROTATE nan\n", "t.scn:4: expected a number with |value| <= 1e9 for the degrees per frame, found 'nan'"},
        {head + "STAFF 2 0 0 0\n", "t.scn:4: tension '2' is outside [-1, 1]"},
        {"FRAMES 10\nOBJECT a\nSHAPE missing.dat\n", "t.scn:3: cannot use 'missing.dat': missing.dat: no such file"},
        {"FRAMES 10\nOBJECT a\nPATHS k1.dat k2.dat\n",
         "t.scn:3: PATHS without KEYS in object 'a'; expected KEYS KEY1.dat KEY2.dat"},
        {"FRAMES 10\nOBJECT a\nKEYS k1.dat k2.dat\nPATHS path.dat path.dat\n",
         "t.scn:4: cannot use 'path.dat': path.dat:3: the path ends at (0, 10, 0); expected the first graphic "
         "point's KEY2 position (0, 0, 2)"},
        {"FRAMES 10\nOBJECT a\nKEYS k1.dat k2.dat FROM 4 TO 4\n",
         "t.scn:3: KEYS FROM 4 TO 4: expected FROM before TO (KEY1 at FROM, KEY2 at TO)"},
        {"FRAMES 10\nVIEW 1 2\nVIEW 1 2\n", "t.scn:3: a second VIEW line; expected one at most"},
        // Issue 44: SPACING, the scene's spacing, once and before the objects whose paths it spaces.
        {"FRAMES 10\nSPACING exact\nVIEW 1 2\nSPACING nearest\nOBJECT a\n",
         "t.scn:4: a second SPACING line; expected one at most"},
        {"FRAMES 10\nSPACING exact\nspacing EXACT\n", "t.scn:3: a second SPACING line; expected one at most"},
        {head + "SPACING exact\n", "t.scn:4: SPACING after an OBJECT line; expected it before the first OBJECT"},
        {"FRAMES 10\nSPACING even\n", "t.scn:2: expected 'SPACING nearest' or 'SPACING exact', found 'even'"},
        {"FRAMES 10\nSPACING 1\n", "t.scn:2: expected 'SPACING nearest' or 'SPACING exact', found '1'"},
        {"FRAMES 10\nSPACING\n", "t.scn:2: expected 'SPACING nearest' or 'SPACING exact'; found nothing after SPACING"},
        {"FRAMES 10\nSPACING exact nearest\n",
         "t.scn:2: expected 'SPACING nearest' or 'SPACING exact', found 'nearest' after 'exact'"},
        {"SPACING exact\nFRAMES 10\n", "t.scn:1: expected 'FRAMES N' as the first data line, found 'SPACING'"},
        {std::string("FRAMES 10\nOBJECT a\x00\n", 20), "t.scn:2: NUL byte; expected a text file"},
    };
    const DatFiles files = example_files();
    for (const Row& row : rows) {
        CAPTURE(row.text);
        const Expected<Scene> scene = parse_scene(row.text, "t.scn", files.reader(), {});
        REQUIRE_FALSE(scene.has_value());
        CHECK(scene.error().to_string() == row.message);
    }
}

TEST_CASE("the scene tree (--tree) prints the scene as the thesis' data structure, parts under their parent", "[scene]")
{
    const Scene scene = scene_from("FRAMES 4\nOBJECT robot\nSTAFF 0.5 0 0 0\nOBJECT head PARENT robot\n"
                                   "SHAPE square.dat\nOBJECT hand PARENT robot\nOBJECT arm PARENT hand\nSHAPE stick.dat\n",
                                   example_files());
    REQUIRE(format_scene_tree(scene, "r.scn") ==
            "r.scn: frames 0-4, 4 objects\n"
            "`-- robot  t c b a +0.50 +0.00 +0.00 +0.00  N=2\n"
            "    |-- head  t c b a +0.50 +0.00 +0.00 +0.00 (inherited)  N=0  SHAPE 4 points\n"
            "    `-- hand  t c b a +0.50 +0.00 +0.00 +0.00 (inherited)  N=1\n"
            "        `-- arm  t c b a +0.50 +0.00 +0.00 +0.00 (inherited)  N=0  SHAPE 2 points\n");
}

TEST_CASE("the scene tree of a deep chain is indented 32 levels at most, deeper nodes saying their depth", "[scene]")
{
    // Issue 33: a 10,000-deep chain printed 200 MB of indentation.
    std::string text = "FRAMES 1\nOBJECT o1\nSHAPE square.dat\n";
    for (int depth = 2; depth <= 100; ++depth)
        text += "OBJECT o" + std::to_string(depth) + " PARENT o" + std::to_string(depth - 1) + "\n";
    const std::string tree = format_scene_tree(scene_from(text, example_files()), "deep.scn");
    std::size_t longest = 0;
    for (std::size_t start = 0, end = 0; start < tree.size(); start = end + 1) {
        end = tree.find('\n', start);
        longest = std::max(longest, end - start);
    }
    CHECK(longest < 4 * 32 + 80);
    CHECK(tree.find("`-- (depth 100) o100  t c b a") != std::string::npos);
    CHECK(tree.find("`-- o32  t c b a") != std::string::npos);
}

TEST_CASE("ROLL RADIUS reads its radius - negative rolls the other way - its AXIS and its hub", "[scene][roll]")
{
    const Scene scene = scene_from("FRAMES 4\nOBJECT a\nSHAPE square.dat\nroll -1.5 ABOUT 0 1 1 AXIS z\n"
                                   "OBJECT b\nSHAPE square.dat\nROLL 2\n",
                                   example_files());
    const SceneRoll& first = *scene.objects[0].roll;
    REQUIRE(first.radius == -1.5);
    REQUIRE(first.axis == Axis::z);
    REQUIRE(first.about == Vec3{0, 1, 1});
    const SceneRoll& second = *scene.objects[1].roll;
    REQUIRE(second.radius == 2.0);
    REQUIRE(second.axis == Axis::x);
    REQUIRE_FALSE(second.about);
    REQUIRE_FALSE(scene.objects[1].rotate);
}
