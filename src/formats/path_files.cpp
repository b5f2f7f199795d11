#include "apcs/formats/path_files.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/number_text.h"

#include <algorithm>
#include <cmath>

namespace apcs {

std::string path_file_name(std::size_t point_number) { return "ani" + std::to_string(point_number) + ".dat"; }

Expected<std::vector<std::filesystem::path>> split_into_path_files(const Graphic& key1, const Graphic& key2,
                                                                   const std::filesystem::path& folder)
{
    const std::vector<Vec3> first = key1.all_points();
    const std::vector<Vec3> second = key2.all_points();
    std::vector<std::filesystem::path> written;
    const std::size_t count = std::min(first.size(), second.size());
    written.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        DatFile path;
        path.parts.push_back({"", Closure::open, {{first[i], std::nullopt, 0}, {second[i], std::nullopt, 0}}});
        const std::filesystem::path target = folder / path_file_name(i + 1);
        const Expected<WriteResult> result = write_file_atomically(target, format_dat(path));
        if (!result)
            return result.error();
        written.push_back(target);
    }
    return written;
}

std::string describe_point(const Vec3& point)
{
    return "(" + shortest_number(point.x) + ", " + shortest_number(point.y) + ", " + shortest_number(point.z) + ")";
}

namespace {

bool same_place(const Vec3& a, const Vec3& b)
{
    const double scale = std::max({1.0, std::abs(a.x), std::abs(a.y), std::abs(a.z)});
    return distance(a, b) <= 1e-6 * scale;
}

} // namespace

std::optional<Diagnostic> check_path_ends(const DatFile& path, const std::string& file_name, const std::string& which,
                                          const Vec3& key1_position, const Vec3& key2_position)
{
    if (path.parts.empty() || path.parts.front().points.empty())
        return Diagnostic{file_name, 0, "has no control points"};
    const DatPoint& start = path.parts.front().points.front();
    const DatPoint& end = path.parts.back().points.back();
    if (!same_place(start.position, key1_position))
        return Diagnostic{file_name, start.line,
                          "the path starts at " + describe_point(start.position) + "; expected the " + which +
                              " graphic point's KEY1 position " + describe_point(key1_position)};
    if (!same_place(end.position, key2_position))
        return Diagnostic{file_name, end.line,
                          "the path ends at " + describe_point(end.position) + "; expected the " + which +
                              " graphic point's KEY2 position " + describe_point(key2_position)};
    return std::nullopt;
}

DatFile dat_from(const ControlPoints& points)
{
    DatFile file;
    file.parts.push_back({"", Closure::open, {}});
    for (const ControlPoint& point : points)
        file.parts[0].points.push_back({point.position, point.staff, 0});
    return file;
}

} // namespace apcs
