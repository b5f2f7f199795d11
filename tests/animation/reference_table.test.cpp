#include "apcs/animation/motion_path.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <algorithm>

using namespace apcs;

namespace {

// The table written by tests/reference/kb_reference.py: a header stating its parameters, then
// "# curve" and "# inbetweens" sections of x y z rows.
struct ReferenceTable {
    ControlPoints points;
    PathSettings settings;
    std::vector<Vec3> curve;
    std::vector<Vec3> inbetweens;
};

ReferenceTable load_reference(const std::string& text)
{
    ReferenceTable table;
    std::vector<Vec3>* section = nullptr;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string line = text.substr(start, end - start);
        start = end + 1;
        double v[7];
        if (std::sscanf(line.c_str(), "; KB reference: slopes %lf %lf, %d samples per segment, %d in-betweens",
                        &table.settings.slopes.start, &table.settings.slopes.end,
                        &table.settings.samples_per_segment, &table.settings.inbetween_count) == 4)
            continue;
        if (line == "# curve")
            section = &table.curve;
        else if (line == "# inbetweens")
            section = &table.inbetweens;
        else if (std::sscanf(line.c_str(), "; %lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5],
                             &v[6]) == 7)
            table.points.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
        else if (section && std::sscanf(line.c_str(), "%lf %lf %lf", &v[0], &v[1], &v[2]) == 3)
            section->push_back({v[0], v[1], v[2]});
    }
    return table;
}

} // namespace

TEST_CASE("the KB curve and its in-betweens match the checked-in reference table to 1e-9", "[animation][reference]")
{
    const ReferenceTable table = load_reference(test::read_all(APCS_SOURCE_DIR "/tests/reference/kb_reference.txt"));
    REQUIRE(table.points.size() == 5);
    REQUIRE(table.settings.samples_per_segment == 8);
    const EvaluatedPath path = evaluate_path(table.points, table.settings);
    REQUIRE(path.curve.points.size() == table.curve.size());
    for (std::size_t i = 0; i < table.curve.size(); ++i) {
        CAPTURE(i);
        REQUIRE(distance(path.curve.points[i], table.curve[i]) < 1e-9);
    }
    REQUIRE(path.inbetweens.size() == table.inbetweens.size());
    for (std::size_t j = 0; j < table.inbetweens.size(); ++j) {
        CAPTURE(j);
        REQUIRE(distance(path.inbetweens[j].position, table.inbetweens[j]) < 1e-9);
    }
}
