#include "apcs/animation/motion_path.h"
#include "apcs/animation/surface_fit.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

using namespace apcs;

namespace {

// The table written by tests/reference/kb_reference.py: a header stating its parameters and the
// first path's control points ("; x y z t c b a"), then sections "# NAME" of number rows.
struct ReferenceTable {
    ControlPoints points;
    PathSettings settings;
    std::map<std::string, std::vector<std::vector<double>>> sections;

    std::vector<Vec3> positions(const std::string& section) const
    {
        std::vector<Vec3> result;
        for (const std::vector<double>& row : sections.at(section))
            result.push_back({row.at(0), row.at(1), row.at(2)});
        return result;
    }
    ControlPoints control_points(const std::string& section) const
    {
        ControlPoints result;
        for (const std::vector<double>& row : sections.at(section))
            result.push_back({{row.at(0), row.at(1), row.at(2)}, {row.at(3), row.at(4), row.at(5), row.at(6)}});
        return result;
    }
};

ReferenceTable load_reference(const std::string& text)
{
    ReferenceTable table;
    std::vector<std::vector<double>>* section = nullptr;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        double v[7];
        if (std::sscanf(line.c_str(), "; KB reference: slopes %lf %lf, %d samples per segment, %d in-betweens",
                        &table.settings.slopes.start, &table.settings.slopes.end,
                        &table.settings.samples_per_segment, &table.settings.inbetween_count) == 4)
            continue;
        if (line.starts_with("# ")) {
            section = &table.sections[line.substr(2, line.find(':') == std::string::npos ? std::string::npos
                                                                                          : line.find(':') - 2)];
        } else if (std::sscanf(line.c_str(), "; %lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4],
                               &v[5], &v[6]) == 7) {
            table.points.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
        } else if (section != nullptr && !line.empty()) {
            std::istringstream numbers(line);
            std::vector<double> row;
            for (double value = 0; numbers >> value;)
                row.push_back(value);
            section->push_back(row);
        }
    }
    return table;
}

const ReferenceTable& reference()
{
    static const ReferenceTable table = load_reference(test::read_all(APCS_SOURCE_DIR "/tests/reference/kb_reference.txt"));
    return table;
}

Graphic open_graphic(std::vector<Vec3> points)
{
    Graphic graphic;
    graphic.parts.push_back({"g", Closure::open, std::move(points)});
    return graphic;
}

} // namespace

TEST_CASE("the KB curve and its in-betweens match the checked-in reference table to 1e-9", "[animation][reference]")
{
    const ReferenceTable& table = reference();
    REQUIRE(table.points.size() == 5);
    REQUIRE(table.settings.samples_per_segment == 8);
    const EvaluatedPath path = evaluate_path(table.points, table.settings);
    const std::vector<Vec3> curve = table.positions("curve");
    REQUIRE(path.curve.sample_count() == curve.size());
    for (std::size_t i = 0; i < curve.size(); ++i) {
        CAPTURE(i);
        REQUIRE(distance(path.curve.sample(i), curve[i]) < 1e-9);
    }
    const std::vector<Vec3> inbetweens = table.positions("inbetweens");
    REQUIRE(path.inbetweens.size() == inbetweens.size());
    for (std::size_t j = 0; j < inbetweens.size(); ++j) {
        CAPTURE(j);
        REQUIRE(distance(path.inbetweens[j].position, inbetweens[j]) < 1e-9);
    }
}

TEST_CASE("exact spacing places the in-betweens at the reference table's arc lengths to 1e-7",
          "[animation][reference][arc-length]")
{
    // The table integrates the length by Gauss-Legendre and inverts it to 1e-15; the program by
    // adaptive Simpson to 1e-10 of the length and bisection to 1e-9 of it.
    const ReferenceTable& table = reference();
    PathSettings exact = table.settings;
    exact.spacing = Spacing::exact;
    const EvaluatedPath path = evaluate_path(table.points, exact);
    const std::vector<Vec3> inbetweens = table.positions("inbetweens exact");
    REQUIRE(inbetweens.size() == 7);
    REQUIRE(path.inbetweens.size() == inbetweens.size());
    for (std::size_t j = 0; j < inbetweens.size(); ++j) {
        CAPTURE(j);
        REQUIRE(distance(path.inbetweens[j].position, inbetweens[j]) < 1e-7);
        // Not the nearest samples: exact spacing is a different placement.
        REQUIRE(distance(path.inbetweens[j].position, table.positions("inbetweens")[j]) > 1e-3);
    }
}

TEST_CASE("surface fitting matches the checked-in reference frames to 1e-9", "[animation][reference][fit]")
{
    const ReferenceTable& table = reference();
    const EqualisedKeys keys{open_graphic(table.positions("key1")), open_graphic(table.positions("key2"))};
    const EvaluatedPath first = evaluate_path(table.points, table.settings);
    const EvaluatedPath last = evaluate_path(table.control_points("last path"), table.settings);
    const FrameSequence frames = fit_key_frames(keys, first, last);
    REQUIRE(frames.frame_count() == static_cast<std::size_t>(table.settings.inbetween_count) + 2);
    for (std::size_t k = 0; k < frames.frame_count(); ++k) {
        const std::vector<Vec3> expected = table.positions("frame " + std::to_string(k));
        REQUIRE(frames.points_per_frame() == expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i) {
            CAPTURE(k, i);
            REQUIRE(distance(frames.frame(k)[i], expected[i]) < 1e-9);
        }
    }
}
