#include "apcs/animation/motion_path.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"
#include "apcs/raster/svg_encoder.h"
#include "apcs/session/path_screen.h"
#include "apcs/session/screen_layout.h"

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
    const ViewTransform view = path_screen_scene(content).fit(ViewAngles{}, layout::view_area);
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

TEST_CASE("apcs fit --svg draws all M+2 frames overlaid", "[cli][svg]")
{
    const TempFolder folder;
    const auto result = run_apcs({"fit", example("key1.dat").string(), example("key2.dat").string(),
                                  example("way1.dat").string(), example("way4.dat").string(), "--inbetweens", "5",
                                  "--svg", (folder / "fit.svg").string()});
    REQUIRE(result.status == 0);
    CHECK(inner_strokes(svg_elements(file_text(folder / "fit.svg"))).size() == 7);
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
    };
    for (const auto& usage : usages) {
        INFO(usage.front() << " " << usage.back());
        const auto result = run_apcs(usage);
        CHECK(result.status == 2);
        CHECK(std::count(result.err.begin(), result.err.end(), '\n') == 2); // the line, then "Try ..."
        CHECK(result.out.empty());
    }
    CHECK(run_apcs({"draw", key}).err.find("--png, --png-raw or --svg") != std::string::npos);
    CHECK(run_apcs({"draw", key, "--svg", "x.png"}).err.find("an SVG file's name ends in .svg") != std::string::npos);
}
