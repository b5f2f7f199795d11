#include "apcs/animation/motion_path.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"
#include "apcs/geometry/hercules.h"
#include "apcs/raster/svg_encoder.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"
#include "apcs/screens/frames_overlay.h"
#include "apcs/screens/path_screen.h"
#include "apcs/raster/screen_layout.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"
#include "support/xml_elements.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;
using test::elements_named;
using test::run_apcs;
using test::TempFolder;
using test::XmlElement;
using test::XmlReader;

namespace {

std::string file_text(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<XmlElement> svg_elements(const std::string& document)
{
    const auto elements = XmlReader::read(document);
    REQUIRE(elements);
    return *elements;
}

// The strokes inside the boundary (clipped): the drawing's own lines, not the frame.
std::vector<XmlElement> inner_strokes(const std::vector<XmlElement>& elements)
{
    std::vector<XmlElement> inner;
    for (const XmlElement& path : elements_named(elements, "path"))
        if (path.attributes.at("class").find(" clipped") != std::string::npos)
            inner.push_back(path);
    return inner;
}

// A stroke's style: the first word of its class.
std::string dashes(const XmlElement& stroke)
{
    const std::string& style_class = stroke.attributes.at("class");
    return style_class.substr(0, style_class.find(' '));
}

std::filesystem::path example(const std::string& name)
{
    return std::filesystem::path(APCS_SOURCE_DIR) / "data" / "n-to-l" / name;
}

// data/NAME/NAME.scn of the source tree.
std::filesystem::path shipped_scene(const std::string& name)
{
    return std::filesystem::path(APCS_SOURCE_DIR) / "data" / name / (name + ".scn");
}

// The overlay of all frames apcs play SCENE --svg - writes.
std::string played_svg(const std::filesystem::path& scene)
{
    const auto result = run_apcs({"play", scene.string(), "--svg", "-"});
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    return result.out;
}

// The text of every element on the row of `first` (the same y), in order: a legend is written in
// parts, each in the colour of the frames it names.
std::string texts_on_row_of(const std::vector<XmlElement>& texts, const XmlElement& first)
{
    std::string row;
    for (const XmlElement& text : texts)
        if (text.attributes.at("y") == first.attributes.at("y"))
            row += text.text;
    return row;
}

} // namespace

TEST_CASE("apcs path --svg holds the path's polyline through the control points' pixels", "[cli][svg]")
{
    const TempFolder folder;
    const auto file = folder.write("way.dat", "0 0 0\n3 -4 5\n0 0 10\n6 2 1\n");
    const auto result = run_apcs({"path", file.string(), "--svg", (folder / "way.svg").string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    REQUIRE(result.out.empty());

    const auto elements = svg_elements(file_text(folder / "way.svg"));
    const auto curves = inner_strokes(elements);
    REQUIRE(curves.size() == 1);
    std::string points = " " + curves[0].attributes.at("d") + " ";
    for (char& letter : points)
        letter = letter == 'M' || letter == 'L' ? ' ' : letter;
    const Expected<DatFile> dat = read_dat_file(file);
    REQUIRE(dat);
    const ControlPoints control = control_points_from(*dat, StaffValues{});
    const EvaluatedPath path = evaluate_path(control, PathSettings{});
    const PathScreenContent content = path_screen_content(control, path);
    const ViewTransform view = path_screen_scene(content).fill(ViewAngles{}, layout::view_area);
    for (const ControlPoint& point : control)
        CHECK(points.find(" " + svg_point_text(view.to_device(point.position).rounded()) + " ") != std::string::npos);
    const auto paths = elements_named(elements, "path");
    const auto marks = std::count_if(paths.begin(), paths.end(), [](const XmlElement& element) {
        return element.attributes.at("class") == "mark";
    });
    CHECK(static_cast<std::size_t>(marks) == control.size() + 4); // the x marks, the staff markers
}

TEST_CASE("apcs draw of three files: the first solid, the middle dotted, the last dashed, and a legend", "[cli][draw]")
{
    const TempFolder folder;
    const auto middle = folder.write("half.dat", "PART letter OPEN\n0 0 5\n0 3 0\n0 3 5\n");
    const auto result = run_apcs({"draw", example("key1.dat").string(), middle.string(), example("key2.dat").string(),
                                  "--view", "front", "--svg", (folder / "three.svg").string(), "--png",
                                  (folder / "three.png").string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    REQUIRE(std::filesystem::exists(folder / "three.png"));

    const auto elements = svg_elements(file_text(folder / "three.svg"));
    const auto lines = inner_strokes(elements);
    REQUIRE(lines.size() == 3);
    CHECK(dashes(lines[0]) == "solid");
    CHECK(dashes(lines[1]) == "dotted");
    CHECK(dashes(lines[2]) == "dashed");
    const auto texts = elements_named(elements, "text");
    REQUIRE(texts.size() == 1);
    CHECK(texts[0].text == "solid: key1.dat  dashed: key2.dat  dotted: half.dat");
}

TEST_CASE("apcs draw lifts the pen between parts and counts the graphics between", "[cli][draw]")
{
    const TempFolder folder;
    std::vector<std::string> arguments{"draw"};
    for (int k = 0; k < 5; ++k)
        arguments.push_back(
            folder.write("g" + std::to_string(k) + ".dat", "PART a OPEN\n0 0 0\n1 1 0\nPART b CLOSED\n3 0 0\n4 0 1\n4 1 1\n")
                .string());
    arguments.insert(arguments.end(), {"--svg", "-"});
    const auto result = run_apcs(arguments);
    REQUIRE(result.status == 0);
    const auto elements = svg_elements(result.out);
    const auto lines = inner_strokes(elements);
    REQUIRE(lines.size() == 10);
    for (std::size_t k = 0; k < lines.size(); ++k)
        CHECK(dashes(lines[k]) == (k < 2 ? "solid" : k >= 8 ? "dashed" : "dotted"));
    CHECK(elements_named(elements, "text").at(0).text == "solid: g0.dat  dashed: g4.dat  dotted: 3 between");
}

TEST_CASE("apcs fit --svg draws all M+2 frames overlaid: KEY1 solid, the in-betweens dotted, KEY2 dashed",
          "[cli][svg][overlay]")
{
    const TempFolder folder;
    const auto result = run_apcs({"fit", example("key1.dat").string(), example("key2.dat").string(),
                                  example("way1.dat").string(), example("way4.dat").string(), "--inbetweens", "5",
                                  "--svg", (folder / "fit.svg").string()});
    REQUIRE(result.status == 0);
    const auto elements = svg_elements(file_text(folder / "fit.svg"));
    const auto lines = inner_strokes(elements);
    REQUIRE(lines.size() == 7);
    for (std::size_t k = 0; k < lines.size(); ++k)
        CHECK(dashes(lines[k]) == (k == 0 ? "solid" : k == 6 ? "dashed" : "dotted"));
    const auto texts = elements_named(elements, "text");
    REQUIRE(texts.size() == 4); // the caption, the legend in three parts (each in its frames' colour)
    CHECK(texts[0].text == "7 frames overlaid: key1.dat to key2.dat");
    CHECK(texts_on_row_of(texts, texts[1]) == "solid: KEY1 key1.dat  dashed: KEY2 key2.dat  dotted: 5 in-betweens");
}

TEST_CASE("apcs play --svg draws frame 0 solid, the last dashed, the others dotted, and names them", "[cli][svg][overlay]")
{
    const auto elements = svg_elements(played_svg(shipped_scene("robot")));
    const auto lines = inner_strokes(elements);
    REQUIRE(lines.size() > 13);
    CHECK(dashes(lines.front()) == "solid");
    CHECK(dashes(lines.back()) == "dashed");
    const auto dotted = std::count_if(lines.begin(), lines.end(), [](const XmlElement& line) { return dashes(line) == "dotted"; });
    CHECK(static_cast<std::size_t>(dotted) * 13 >= lines.size() * 10); // frames 1-11 of 0-12
    const auto texts = elements_named(elements, "text");
    REQUIRE(texts.size() == 4);
    CHECK(texts_on_row_of(texts, texts[1]) == "solid: frame 0  dashed: frame 12  dotted: frames 1-11");
}

TEST_CASE("apcs play letters the car's waypoints A–D: an x on each, its letter in the cell under it", "[cli][svg][overlay]")
{
    const std::filesystem::path car = shipped_scene("car");
    const std::string svg = played_svg(car);
    const auto elements = svg_elements(svg);

    const Expected<Scene> scene = read_scene_file(car, StaffValues{});
    REQUIRE(scene);
    PathSettings settings;
    settings.spacing = Spacing::exact;
    const SceneAnimation animation(*scene, settings);
    const std::vector<TimedWaypoint> waypoints = timed_waypoints(*scene, animation);
    // The road's control points (road.dat), at the frames TIMES gives them.
    REQUIRE(waypoints.size() == 4);
    const std::vector<Vec3> road{{0, 0, 0}, {0, 10, 3}, {0, 25, 0}, {0, 40, 2}};
    const std::vector<int> times{0, 10, 35, 60};
    const ViewTransform view = frames_view(animation.all_frames(), *scene->view);
    const auto texts = elements_named(elements, "text");
    for (std::size_t k = 0; k < waypoints.size(); ++k) {
        CHECK(waypoints[k].frame == times[k]);
        CHECK(distance(waypoints[k].position, road[k]) < 1e-12);
        const PixelPoint at = view.to_device(waypoints[k].position).rounded();
        const std::string letter(1, static_cast<char>('A' + k));
        INFO(letter << " at " << at.x << "," << at.y);
        // The x: its first stroke runs from 2 pixels up and left of the point.
        CHECK(svg.find("class=\"mark\" d=\"M" + svg_point_text({at.x - 2, at.y - 2}) + " L") != std::string::npos);
        const auto text = std::find_if(texts.begin(), texts.end(), [&](const XmlElement& t) { return t.text == letter; });
        REQUIRE(text != texts.end());
        const double x = std::stod(text->attributes.at("x"));
        const double baseline = std::stod(text->attributes.at("y")) / svg_row_height;
        CHECK(x <= at.x);
        CHECK(x > at.x - hercules::cell_width);
        CHECK(baseline > at.y + 2);
        CHECK(baseline < at.y + 2 + 2 * hercules::cell_height);
    }
    CHECK(std::any_of(texts.begin(), texts.end(),
                      [](const XmlElement& t) { return t.text == "A-D: car at frames 0, 10, 35, 60"; }));
    CHECK(std::any_of(texts.begin(), texts.end(), [&](const XmlElement& t) {
        return texts_on_row_of(texts, t) == "solid: frame 0  dashed: frame 60  dotted: frames 1-59";
    }));
}

TEST_CASE("apcs draw: bad input is exit 1 naming the file and line", "[cli][draw]")
{
    const TempFolder folder;
    const auto bad = folder.write("bad.dat", "0 0 0\n1 x 2\n");
    const auto result = run_apcs({"draw", example("key1.dat").string(), bad.string(), "--svg", (folder / "o.svg").string()});
    CHECK(result.status == 1);
    CHECK(result.err.find("bad.dat:2:") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(folder / "o.svg"));
    const auto missing = run_apcs({"draw", (folder / "none.dat").string(), "--svg", (folder / "o.svg").string()});
    CHECK(missing.status == 1);
    CHECK(missing.err.find("none.dat") != std::string::npos);
}

TEST_CASE("a picture name of the wrong kind, or draw without a picture, is exit 2 with one line", "[cli][draw]")
{
    const std::string key = example("key1.dat").string();
    const std::vector<std::vector<std::string>> usages{
        {"draw", key},
        {"draw", "--svg", "x.svg"},
        {"draw", key, "--svg", "x.png"},
        {"draw", key, "--png", "x.svg"},
        {"path", key, "--svg", "x.txt"},
        {"inbetween", key, key, "--svg", "x.png"},
        {"--svg", "-"},
        {"draw", key, "--svg", "-", "--png", "-"},
        {"draw", key, "--sixel", "x.png"},
        {"path", key, "--kitty", "x.six"},
        {"draw", key, "--sixel", "-", "--kitty", "-"},
        {"path", key, "--sixel", "x", "--kitty", "x"},
    };
    for (const auto& usage : usages) {
        INFO(usage.front() << " " << usage.back());
        const auto result = run_apcs(usage);
        CHECK(result.status == 2);
        CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 2); // the line, then "Try ..."
        CHECK(result.out.empty());
    }
    CHECK(run_apcs({"draw", key}).err.find("--png, --png-raw, --svg, --sixel or --kitty") != std::string::npos);
    CHECK(run_apcs({"draw", key, "--sixel", "x.png"}).err.find("a sixel file's name ends in .six or .sixel") !=
          std::string::npos);
    CHECK(run_apcs({"path", key, "--kitty", "x.six"}).err.find("a kitty picture's name ends in .kitty") !=
          std::string::npos);
    CHECK(run_apcs({"draw", key, "--svg", "x.png"}).err.find("an SVG file's name ends in .svg") != std::string::npos);
}
