#include "apcs/formats/sif_path.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <string>

using namespace apcs;

namespace {

// The document of the issue, as `apcs export` and Synfig 1.4 write it: the waypoints open on lines
// 10 and 13.
const std::string issue_document = R"(<?xml version="1.0" encoding="UTF-8"?>
<canvas version="1.2" width="480" height="270" xres="2834.645669" yres="2834.645669" view-box="-4 2.25 4 -2.25" antialias="1" fps="24" begin-time="0f" end-time="48f" bgcolor="1 1 1 1">
  <name>...</name>
  <layer type="circle" active="true" exclude_from_rendering="false" version="0.2" desc="point">
    <param name="z_depth"><real value="0"/></param>
    <param name="color"><color><r>1</r><g>0</g><b>0</b><a>1</a></color></param>
    <param name="radius"><distance distance="0.1" unit="units"/></param>
    <param name="origin">
      <animated type="vector">
        <waypoint time="0f" before="auto" after="auto" tension="0.5" continuity="0" bias="-0.2" temporal-tension="0">
          <vector><x>1.5</x><y>-2</y></vector>
        </waypoint>
        <waypoint time="12f" before="auto" after="auto" tension="0" continuity="0" bias="0" temporal-tension="0">
          <vector><x>3</x><y>0.25</y></vector>
        </waypoint>
      </animated>
    </param>
  </layer>
</canvas>
)";

// A document whose lines are: 1 the XML declaration, 2 <canvas>, then `body`.
std::string canvas(const std::string& body, const std::string& canvas_attributes = "fps=\"24\"")
{
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<canvas version=\"1.2\" " + canvas_attributes + ">\n" + body +
           "</canvas>\n";
}

// A layer of lines: `layer_line` <layer>, + 1 <param name="PARAM">, + 2 <animated type="TYPE">, + 3 …
// the waypoints, one a line.
std::string animated_layer(const std::string& waypoints, const std::string& param = "origin",
                           const std::string& type = "vector")
{
    return "<layer type=\"circle\" desc=\"point\">\n<param name=\"" + param + "\">\n<animated type=\"" + type +
           "\">\n" + waypoints + "</animated>\n</param>\n</layer>\n";
}

// A waypoint on one line; without attributes its interpolations are TCB and its staff values 0.
std::string waypoint(const std::string& time, const std::string& x, const std::string& y,
                     const std::string& attributes = "")
{
    return "<waypoint time=\"" + time + "\"" + attributes + "><vector><x>" + x +
           "</x><y>" + y + "</y></vector></waypoint>\n";
}

// A root layer whose animated origin opens on line 5 and whose waypoints are on lines 6, 7, …
std::string path_document(const std::string& waypoints, const std::string& canvas_attributes = "fps=\"24\"")
{
    return canvas(animated_layer(waypoints), canvas_attributes);
}

SifPath accepted(const std::string& text, const SifReading& reading = {})
{
    Expected<SifPath> path = parse_sif_path(text, "walk.sif", reading);
    if (!path)
        FAIL(path.error().to_string());
    return std::move(*path);
}

std::string rejection(const std::string& text, const SifReading& reading = {})
{
    const Expected<SifPath> path = parse_sif_path(text, "walk.sif", reading);
    REQUIRE_FALSE(path.has_value());
    return path.error().to_string();
}

const std::vector<DatPoint>& points_of(const SifPath& path)
{
    REQUIRE(path.file.parts.size() == 1);
    return path.file.parts[0].points;
}

} // namespace

TEST_CASE("the issue's document reads as two control points with their staff values and lines", "[formats][sif]")
{
    const SifPath path = accepted(issue_document);
    REQUIRE(path.file.parts.size() == 1);
    CHECK(path.file.parts[0].closure == Closure::open);
    CHECK(path.file.parts[0].name.empty());
    CHECK_FALSE(path.file.slopes.has_value());
    const std::vector<DatPoint>& points = points_of(path);
    REQUIRE(points.size() == 2);
    CHECK(points[0].position == Vec3{1.5, -2, 0});
    CHECK(points[0].staff == StaffValues{0.5, 0, -0.2, 0});
    CHECK(points[0].line == 10);
    CHECK(points[1].position == Vec3{3, 0.25, 0});
    CHECK(points[1].staff == StaffValues{0, 0, 0, 0});
    CHECK(points[1].line == 13);
    CHECK(path.warnings.empty());
}

TEST_CASE("the vector (u, v) is read into the plane the view looks at", "[formats][sif]")
{
    SifReading reading;
    SECTION("front: (0, u, v)")
    {
        reading.plane = SifPlane::front;
        const SifPath path = accepted(issue_document, reading);
        CHECK(points_of(path)[0].position == Vec3{0, 1.5, -2});
        CHECK(points_of(path)[1].position == Vec3{0, 3, 0.25});
    }
    SECTION("side: (u, 0, v)")
    {
        reading.plane = SifPlane::side;
        const SifPath path = accepted(issue_document, reading);
        CHECK(points_of(path)[0].position == Vec3{1.5, 0, -2});
        CHECK(points_of(path)[1].position == Vec3{3, 0, 0.25});
    }
}

TEST_CASE("waypoints are sorted by time, as Synfig keeps them, each with its own line", "[formats][sif]")
{
    const SifPath path = accepted(path_document(waypoint("24f", "3", "3", " tension=\"-1\"") +
                                                waypoint("0f", "1", "1", " continuity=\"1\"") +
                                                waypoint("12", "2", "2", " bias=\"0.25\"")));
    const std::vector<DatPoint>& points = points_of(path);
    REQUIRE(points.size() == 3);
    CHECK(points[0].position == Vec3{1, 1, 0});
    CHECK(points[0].staff == StaffValues{0, 1, 0, 0});
    CHECK(points[0].line == 7);
    CHECK(points[1].position == Vec3{2, 2, 0});
    CHECK(points[1].staff == StaffValues{0, 0, 0.25, 0});
    CHECK(points[1].line == 8);
    CHECK(points[2].position == Vec3{3, 3, 0});
    CHECK(points[2].staff == StaffValues{-1, 0, 0, 0});
    CHECK(points[2].line == 6);
    CHECK(path.warnings.empty());
}

TEST_CASE("waypoints at unequal times are read, with a warning that APCS spaces them equally", "[formats][sif]")
{
    SECTION("three waypoints: every frame is named")
    {
        const SifPath path =
            accepted(path_document(waypoint("0f", "0", "0") + waypoint("12f", "1", "0") + waypoint("30f", "2", "0")));
        CHECK(points_of(path).size() == 3);
        REQUIRE(path.warnings.size() == 1);
        CHECK(path.warnings[0] == "walk.sif:8: the waypoints are not equally spaced in time (frames 0, 12, 30); "
                                  "APCS spaces them equally, so the curve differs from Synfig's");
    }
    SECTION("many waypoints: the first span and the first that differs")
    {
        std::string waypoints;
        for (int frame : {0, 10, 20, 30, 40, 50, 65, 75})
            waypoints += waypoint(std::to_string(frame) + "f", std::to_string(frame), "0");
        const SifPath path = accepted(path_document(waypoints));
        REQUIRE(path.warnings.size() == 1);
        CHECK(path.warnings[0] == "walk.sif:12: the waypoints are not equally spaced in time "
                                  "(frames 0, 10, …, 50, 65, …); APCS spaces them equally, so the curve differs "
                                  "from Synfig's");
    }
}

TEST_CASE("times are read in Synfig's units at the canvas's frame rate", "[formats][sif]")
{
    SECTION("'1s 12f' is frame 36 at 24 fps, '3s' frame 72, a bare number frames: equally spaced")
    {
        const SifPath path =
            accepted(path_document(waypoint("0", "0", "0") + waypoint("1s 12f", "1", "0") + waypoint("3s", "2", "0")));
        CHECK(points_of(path).size() == 3);
        CHECK(path.warnings.empty());
    }
    SECTION("'1s 12f' and '36' are one time")
    {
        CHECK(rejection(path_document(waypoint("36", "0", "0") + waypoint("1s 12f", "1", "0"))) ==
              "walk.sif:7: a second waypoint at frame 36 (the first is at line 6); a path passes each time once");
    }
    SECTION("hours, minutes and seconds at the canvas's fps")
    {
        const SifPath path =
            accepted(path_document(waypoint("0h", "0", "0") + waypoint("0.5s", "1", "0") + waypoint("1S", "2", "0") +
                                       waypoint("0.025m", "3", "0"),
                                   "fps=\"12\""));
        CHECK(points_of(path).size() == 4);
        CHECK(path.warnings.empty());
    }
    SECTION("no fps attribute: 24 frames a second")
    {
        const SifPath path =
            accepted(path_document(waypoint("0f", "0", "0") + waypoint("24f", "1", "0") + waypoint("2s", "2", "0"),
                                   ""));
        CHECK(path.warnings.empty());
    }
}

TEST_CASE("times APCS cannot space are refused with their line", "[formats][sif]")
{
    CHECK(rejection(path_document(waypoint("SOT", "0", "0") + waypoint("1s", "1", "0"))) ==
          "walk.sif:6: time=\"SOT\" is the start or end of all time, which APCS cannot space; expected NUMBER UNIT "
          "pairs with units h, m, s, f (\"12f\", \"0.5s\", \"1s 12f\")");
    CHECK(rejection(path_document(waypoint("0f", "0", "0") + waypoint("00:00:01.12", "1", "0"))) ==
          "walk.sif:7: time=\"00:00:01.12\" is in the hh:mm:ss form, which APCS does not read; expected NUMBER UNIT "
          "pairs with units h, m, s, f (\"12f\", \"0.5s\", \"1s 12f\")");
    CHECK(rejection(path_document(waypoint("0f", "0", "0") + waypoint("2d", "1", "0"))) ==
          "walk.sif:7: time=\"2d\" has the unknown unit 'd'; expected NUMBER UNIT pairs with units h, m, s, f "
          "(\"12f\", \"0.5s\", \"1s 12f\")");
    CHECK(rejection(path_document(waypoint("0f", "0", "0") + waypoint("nanf", "1", "0"))) ==
          "walk.sif:7: time=\"nanf\" is not a time APCS reads; expected NUMBER UNIT pairs with units h, m, s, f "
          "(\"12f\", \"0.5s\", \"1s 12f\"), each number finite and within 1e9");
    CHECK(rejection(path_document("<waypoint><vector><x>0</x><y>0</y></vector></waypoint>\n")) ==
          "walk.sif:6: a <waypoint> without a time; expected time=\"12f\" or the like");
    CHECK(rejection(path_document(waypoint("0f", "0", "0"), "fps=\"0\"")) ==
          "walk.sif:2: fps=\"0\" is not a frame rate; expected a number above 0 and within 1e9");
}

TEST_CASE("--sif-param reads another animated vector, and a static one is passed over", "[formats][sif]")
{
    const std::string static_origin =
        "<layer type=\"circle\">\n<param name=\"origin\"><vector><x>9</x><y>9</y></vector></param>\n</layer>\n";
    const std::string document =
        canvas(static_origin + animated_layer(waypoint("0f", "1", "2") + waypoint("12f", "3", "4"), "offset") +
               animated_layer(waypoint("0f", "5", "6") + waypoint("12f", "7", "8")));
    SECTION("origin: the first layer's is static, the third layer's is read")
    {
        const SifPath path = accepted(document);
        CHECK(points_of(path)[0].position == Vec3{5, 6, 0});
        CHECK(points_of(path)[0].line == 17);
    }
    SECTION("--sif-param offset")
    {
        SifReading reading;
        reading.param = "offset";
        const SifPath path = accepted(document, reading);
        CHECK(points_of(path)[0].position == Vec3{1, 2, 0});
        CHECK(points_of(path)[1].position == Vec3{3, 4, 0});
        CHECK(points_of(path)[1].line == 10);
    }
    SECTION("a parameter no layer animates")
    {
        SifReading reading;
        reading.param = "center";
        CHECK(rejection(document, reading) == "walk.sif: no layer has an animated vector `center` (the root canvas "
                                              "has 3 layers); apcs path --sif-param names another parameter");
    }
}

TEST_CASE("a document without an animated origin is refused, saying what it has", "[formats][sif]")
{
    SECTION("only static origins")
    {
        const std::string layer =
            "<layer type=\"circle\">\n<param name=\"origin\"><vector><x>9</x><y>9</y></vector></param>\n</layer>\n";
        CHECK(rejection(canvas(layer + layer)) == "walk.sif: no layer has an animated vector `origin` (the root canvas "
                                                  "has 2 layers, 2 with a static `origin`); apcs path --sif-param names "
                                                  "another parameter");
    }
    SECTION("no layers")
    {
        CHECK(rejection(canvas("<name>empty</name>\n")) ==
              "walk.sif: no layer has an animated vector `origin` (the root canvas has 0 layers); apcs path "
              "--sif-param names another parameter");
    }
    SECTION("an origin converted to another value node is named with its line")
    {
        const std::string layer = "<layer type=\"circle\">\n<param name=\"origin\">\n<composite type=\"vector\">"
                                  "<x><real value=\"1\"/></x><y><real value=\"2\"/></y></composite>\n</param>\n"
                                  "</layer>\n";
        CHECK(rejection(canvas(layer)) ==
              "walk.sif: no layer has an animated vector `origin` (the root canvas has 1 layer; at line 5 `origin` is "
              "<composite>, a converted value, which APCS does not read); apcs path --sif-param names another parameter");
    }
    SECTION("an origin linked to an exported value is named with its line")
    {
        const std::string layer = "<layer type=\"circle\">\n<param name=\"origin\" use=\"walk\"/>\n</layer>\n";
        CHECK(rejection(canvas(layer)) == "walk.sif: no layer has an animated vector `origin` (the root canvas has 1 "
                                          "layer; at line 4 `origin` is linked to the exported value use=\"walk\", "
                                          "which APCS does not read); apcs path --sif-param names another parameter");
    }
}

TEST_CASE("an origin animated as another type is refused on its line", "[formats][sif]")
{
    const std::string layer = "<layer type=\"circle\">\n<param name=\"origin\">\n<animated type=\"real\">\n"
                              "<waypoint time=\"0f\"><real value=\"1\"/></waypoint>\n</animated>\n</param>\n</layer>\n";
    CHECK(rejection(canvas(layer)) == "walk.sif:5: `origin` is animated as type \"real\", not as a vector; APCS reads "
                                      "an animated vector (<animated type=\"vector\">)");
}

TEST_CASE("an origin animated inside a group's canvas is refused: a parent would move it", "[formats][sif]")
{
    const std::string group = "<layer type=\"group\" desc=\"walker\">\n"
                              "<param name=\"canvas\">\n<canvas>\n" +
                              animated_layer(waypoint("0f", "0", "0") + waypoint("12f", "1", "1")) +
                              "</canvas>\n</param>\n</layer>\n";
    CHECK(rejection(canvas(group)) ==
          "walk.sif:8: `origin` is animated in a layer of a nested canvas (a group's or an exported one); APCS reads "
          "the layers of the root canvas only, since a parent layer's transformation would move the path");
    SECTION("a root layer before the group is read")
    {
        const SifPath path =
            accepted(canvas(animated_layer(waypoint("0f", "5", "5") + waypoint("12f", "6", "6")) + group));
        CHECK(points_of(path)[0].position == Vec3{5, 5, 0});
    }
}

TEST_CASE("a waypoint that is not a literal vector is refused on its line", "[formats][sif]")
{
    SECTION("linked by use=")
    {
        CHECK(rejection(path_document(waypoint("0f", "0", "0") + "<waypoint time=\"12f\" use=\"spot\"/>\n")) ==
              "walk.sif:7: the waypoint's value is linked (use=\"spot\"), not a literal <vector>; APCS reads waypoints "
              "with their own values only");
    }
    SECTION("a converted value node")
    {
        CHECK(rejection(path_document(waypoint("0f", "0", "0") +
                                      "<waypoint time=\"12f\">\n<add type=\"vector\"><lhs><vector><x>0</x><y>0</y>"
                                      "</vector></lhs></add></waypoint>\n")) ==
              "walk.sif:8: the waypoint's value is <add> (a converted value), not a literal <vector>; APCS reads "
              "waypoints with their own values only");
    }
    SECTION("the animated node itself linked")
    {
        const std::string layer = "<layer type=\"circle\">\n<param name=\"origin\">\n"
                                  "<animated type=\"vector\" use=\"walk\"></animated>\n</param>\n</layer>\n";
        CHECK(rejection(canvas(layer)) == "walk.sif:5: the animated `origin` is linked (use=\"walk\"); APCS reads "
                                          "waypoints written in the document only");
    }
    SECTION("a vector without its y")
    {
        CHECK(rejection(path_document(waypoint("0f", "0", "0") +
                                      "<waypoint time=\"12f\"><vector><x>1</x></vector></waypoint>\n")) ==
              "walk.sif:7: the vector has no <y>; expected <x> and <y>");
    }
    SECTION("a second value after the vector")
    {
        CHECK(rejection(path_document("<waypoint time=\"0f\"><vector><x>0</x><y>0</y></vector>\n"
                                      "<vector><x>1</x><y>1</y></vector></waypoint>\n")) ==
              "walk.sif:7: a second value in the waypoint, <vector>; expected one <vector>");
    }
    SECTION("a vector with a z")
    {
        const std::string waypoint_with_z =
            "<waypoint time=\"0f\"><vector><x>0</x><y>0</y><z>0</z></vector></waypoint>\n";
        CHECK(rejection(path_document(waypoint_with_z)) ==
              "walk.sif:6: expected <x> or <y> in the vector, found <z>");
    }
    SECTION("a number longer than any Synfig writes")
    {
        CHECK(rejection(path_document(waypoint("0f", std::string(300, '1'), "0"))) ==
              "walk.sif:6: the number in <x> is longer than 256 characters");
    }
    SECTION("an element inside a coordinate")
    {
        CHECK(rejection(path_document(waypoint("0f", "<real value=\"1\"/>", "0"))) ==
              "walk.sif:6: expected a number in <x>, found the element <real>");
    }
}

TEST_CASE("interpolations other than TCB between the first and last waypoint are refused", "[formats][sif]")
{
    const std::string first = "<waypoint time=\"0f\" before=\"clamped\" after=\"auto\"><vector><x>0</x><y>0</y>"
                              "</vector></waypoint>\n";
    const std::string last = "<waypoint time=\"24f\" before=\"auto\" after=\"halt\"><vector><x>2</x><y>0</y>"
                             "</vector></waypoint>\n";
    SECTION("the first waypoint's before and the last one's after shape nothing: read")
    {
        const SifPath path = accepted(path_document(first + waypoint("12f", "1", "0") + last));
        CHECK(points_of(path).size() == 3);
    }
    SECTION("after=\"clamped\" on a middle waypoint")
    {
        const std::string middle = "<waypoint time=\"12f\" before=\"auto\" after=\"clamped\"><vector><x>1</x>"
                                   "<y>0</y></vector></waypoint>\n";
        CHECK(rejection(path_document(first + middle + last)) ==
              "walk.sif:7: interpolation after=\"clamped\"; APCS reads TCB waypoints only (auto)");
    }
    SECTION("before=\"linear\" on the last waypoint")
    {
        CHECK(rejection(path_document(waypoint("0f", "0", "0") + waypoint("12f", "1", "0", " before=\"linear\""))) ==
              "walk.sif:7: interpolation before=\"linear\"; APCS reads TCB waypoints only (auto)");
    }
    SECTION("a value Synfig does not write")
    {
        CHECK(rejection(path_document(waypoint("0f", "0", "0", " after=\"bouncy\""))) ==
              "walk.sif:6: after=\"bouncy\" is no interpolation Synfig writes (auto, clamped, constant, ease, halt, "
              "linear, manual)");
    }
}

TEST_CASE("temporal tension is read with a warning that APCS ignores it", "[formats][sif]")
{
    const SifPath path = accepted(path_document(waypoint("0f", "0", "0", " temporal-tension=\"0.5\"") +
                                                waypoint("12f", "1", "0", " temporal-tension=\"-1\"") +
                                                waypoint("24f", "2", "0")));
    CHECK(points_of(path).size() == 3);
    REQUIRE(path.warnings.size() == 1);
    CHECK(path.warnings[0] == "walk.sif:6: temporal-tension=\"0.5\" (and 1 more waypoint): APCS ignores temporal "
                              "tension, so the path's timing differs from Synfig's");
}

TEST_CASE("numbers are refused as SPEC 2.1 refuses them, with their line", "[formats][sif]")
{
    CHECK(rejection(path_document(waypoint("0f", "0", "0") + waypoint("12f", "nan", "0"))) ==
          "walk.sif:7: expected a finite number in <x>, found 'nan'");
    CHECK(rejection(path_document(waypoint("0f", "0", "-inf") + waypoint("12f", "0", "0"))) ==
          "walk.sif:6: expected a finite number in <y>, found '-inf'");
    CHECK(rejection(path_document(waypoint("0f", "0", "0") + waypoint("12f", "1e10", "0"))) ==
          "walk.sif:7: number '1e10' in <x> is out of range; expected |value| <= 1e9");
    CHECK(rejection(path_document(waypoint("0f", "1,5", "0") + waypoint("12f", "0", "0"))) ==
          "walk.sif:6: expected a number in <x>, found '1,5'");
    CHECK(rejection(path_document(waypoint("0f", "0", "0", " tension=\"2\"") + waypoint("12f", "0", "0"))) ==
          "walk.sif:6: tension=\"2\" is outside [-1, 1]");
    CHECK(rejection(path_document(waypoint("0f", "0", "0", " bias=\"NaN\"") + waypoint("12f", "0", "0"))) ==
          "walk.sif:6: expected a finite number in bias=\"NaN\"");
    CHECK(rejection(path_document(waypoint("0f", "0", "0", " continuity=\"half\"") + waypoint("12f", "0", "0"))) ==
          "walk.sif:6: expected a number in continuity=\"half\"");
}

TEST_CASE("numbers keep their '.' whatever the locale, and may carry blanks and exponents", "[formats][sif]")
{
    const SifPath path =
        accepted(path_document(waypoint("0f", " 1.25e1\n", "\t-0.5 ") +
                               waypoint("12f", "+2", "3E-1", " tension=\" .5\"")));
    CHECK(points_of(path)[0].position == Vec3{12.5, -0.5, 0});
    CHECK(points_of(path)[1].position == Vec3{2, 0.3, 0});
    CHECK(points_of(path)[1].staff == StaffValues{0.5, 0, 0, 0});
}

TEST_CASE("a path needs two waypoints at different times", "[formats][sif]")
{
    CHECK(rejection(path_document(waypoint("0f", "0", "0"))) ==
          "walk.sif:5: the animated `origin` has 1 waypoint; a path needs at least 2");
    CHECK(rejection(path_document("")) == "walk.sif:5: the animated `origin` has 0 waypoints; a path needs at least 2");
    CHECK(rejection(path_document(waypoint("12f", "0", "0") + waypoint("0f", "1", "0") + waypoint("12f", "2", "0"))) ==
          "walk.sif:8: a second waypoint at frame 12 (the first is at line 6); a path passes each time once");
}

TEST_CASE("more than 10^6 waypoints are refused at the one over the limit", "[formats][sif][memory]")
{
    // Written in place: the 70 MB document is not copied.
    std::string document = path_document("");
    const std::size_t path_end = document.find("</animated>");
    const std::string tail = document.substr(path_end);
    const std::string one = "<waypoint time=\"1\"><vector><x>0</x><y>0</y></vector></waypoint>\n";
    document.resize(path_end);
    document.reserve(path_end + one.size() * (max_dat_points + 2) + tail.size());
    for (std::size_t i = 0; i <= max_dat_points + 1; ++i)
        document += one;
    document += tail;
    CHECK(rejection(document) == "walk.sif:" + std::to_string(6 + max_dat_points) +
                                     ": more than 1000000 waypoints; a path has at most that many");
}

TEST_CASE("an entity declaration is refused as it is met: billion laughs", "[formats][sif][security]")
{
    std::string document = "<?xml version=\"1.0\"?>\n<!DOCTYPE canvas [\n<!ENTITY lol \"lol\">\n";
    for (int level = 1; level <= 9; ++level) {
        const std::string below = level == 1 ? "lol" : "lol" + std::to_string(level - 1);
        document += "<!ENTITY lol" + std::to_string(level) + " \"";
        for (int i = 0; i < 10; ++i)
            document += "&" + below + ";";
        document += "\">\n";
    }
    document += "]>\n<canvas fps=\"24\">&lol9;</canvas>\n";
    const auto start = std::chrono::steady_clock::now();
    CHECK(rejection(document) ==
          "walk.sif:3: declares the entity lol; a Synfig document declares none, and APCS expands none");
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(2));
}

TEST_CASE("external entities and other DTD declarations are refused", "[formats][sif][security]")
{
    CHECK(rejection("<?xml version=\"1.0\"?>\n<!DOCTYPE canvas [\n<!ENTITY secret SYSTEM \"file:///etc/passwd\">\n]>\n"
                    "<canvas>&secret;</canvas>\n") ==
          "walk.sif:3: declares the entity secret; a Synfig document declares none, and APCS expands none");
    CHECK(rejection("<?xml version=\"1.0\"?>\n<!DOCTYPE canvas [\n<!ENTITY % remote SYSTEM "
                    "\"http://example.org/evil.dtd\">\n%remote;\n]>\n<canvas/>\n") ==
          "walk.sif:3: declares the parameter entity %remote; a Synfig document declares none, and APCS expands none");
    CHECK(rejection("<?xml version=\"1.0\"?>\n<!DOCTYPE canvas [\n<!ATTLIST waypoint before CDATA \"clamped\">\n]>\n"
                    "<canvas/>\n") == "walk.sif:3: declares attributes of <waypoint>; a Synfig document declares none, "
                                      "and APCS takes none from a DTD");
    CHECK(rejection("<?xml version=\"1.0\"?>\n<!DOCTYPE canvas SYSTEM \"synfig.dtd\">\n<canvas>\n&name;</canvas>\n") ==
          "walk.sif:4: refers to the entity name, which APCS does not expand; a Synfig document uses none");
}

TEST_CASE("text that is not a Synfig document is refused with expat's reason", "[formats][sif]")
{
    CHECK(rejection("") == "walk.sif:1: not a Synfig document: no element found");
    CHECK(rejection("0 0 0\n1 1 1\n") == "walk.sif:1: not a Synfig document: syntax error");
    CHECK(rejection(canvas("<layer>\n</param>\n")) == "walk.sif:4: not a Synfig document: mismatched tag");
    CHECK(rejection("<?xml version=\"1.0\"?>\n<svg width=\"10\"/>\n") ==
          "walk.sif:2: not a Synfig document: the root element is <svg>, expected <canvas>");
    SECTION("a malformed tail after the path is refused too")
    {
        const std::string document = path_document(waypoint("0f", "0", "0") + waypoint("12f", "1", "0"));
        CHECK(rejection(document + "<canvas>\n") == "walk.sif:12: not a Synfig document: junk after document element");
    }
}

TEST_CASE("a 32 MiB attribute is read whole, a piece at a time", "[formats][sif][memory]")
{
    // Expat 2.5 scans an unfinished token again with each piece of text it is given, so the pieces
    // grow with what it holds; bench/sif_path.bench.cpp (read_long_attribute) times 4 and 32 MiB.
    const std::string document = canvas("<layer desc=\"" + std::string(32u << 20, 'w') + "\"/>\n");
    CHECK(rejection(document) == "walk.sif: no layer has an animated vector `origin` (the root canvas has 1 "
                                 "layer); apcs path --sif-param names another parameter");
}

TEST_CASE("elements nested past 1000 deep are refused where they pass it, before or after the path",
          "[formats][sif][memory]")
{
    std::string deep;
    for (std::size_t level = 0; level < most_nested_elements; ++level)
        deep += "<a>";
    // The canvas is the first element: 999 more fit, the 1000th <a> is the 1001st element.
    const std::string document = "<?xml version=\"1.0\"?>\n<canvas>\n" + deep + "\n</canvas>\n";
    CHECK(rejection(document) == "walk.sif:3: elements nested more than 1000 deep; a Synfig document nests a few dozen");
    const std::string after_path = path_document(waypoint("0f", "0", "0") + waypoint("12f", "1", "0"));
    const std::size_t end = after_path.rfind("</canvas>");
    CHECK(rejection(after_path.substr(0, end) + deep + "\n" + after_path.substr(end))
              .ends_with("elements nested more than 1000 deep; a Synfig document nests a few dozen"));
}
