#include "apcs/formats/path_files.h"

#include "apcs/formats/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace apcs {

std::string path_file_name(std::size_t point_number) { return "ani" + std::to_string(point_number) + ".dat"; }

std::vector<NamedText> split_path_files(const Graphic& key1, const Graphic& key2)
{
    const std::vector<Vec3> first = key1.all_points();
    const std::vector<Vec3> second = key2.all_points();
    const std::size_t count = std::min(first.size(), second.size());
    std::vector<NamedText> files;
    files.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
        files.push_back(split_path_file(i + 1, first[i], second[i]));
    return files;
}

NamedText split_path_file(std::size_t point_number, const Vec3& key1_point, const Vec3& key2_point)
{
    DatFile path;
    path.parts.push_back({"", Closure::open, {{key1_point, std::nullopt, 0}, {key2_point, std::nullopt, 0}}});
    return {path_file_name(point_number), format_dat(path)};
}

std::string inbetween_file_name(std::size_t number)
{
    char name[32];
    std::snprintf(name, sizeof name, "inb%03zu.dat", number);
    return name;
}

std::size_t inbetween_count(const FrameSequence& frames)
{
    return frames.frame_count() < 2 ? 0 : frames.frame_count() - 2;
}

NamedText inbetween_file(const FrameSequence& frames, const Graphic& structure, std::size_t number)
{
    return {inbetween_file_name(number), "; APCS in-between " + std::to_string(number) + " of " +
                                             std::to_string(inbetween_count(frames)) + "\n" +
                                             format_graphic(structure, frames.frame(number))};
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

ControlPoints control_points_from(const DatFile& file, const StaffValues& defaults)
{
    ControlPoints points;
    points.reserve(file.point_count());
    for (const DatPart& part : file.parts)
        for (const DatPoint& point : part.points)
            points.push_back({point.position, point.staff.value_or(defaults)});
    return points;
}

Expected<ControlPoints> point_path_from(const DatFile& file, const std::string& file_name, PathEnd end,
                                        const EqualisedKeys& keys, const StaffValues& defaults)
{
    const bool first = end == PathEnd::first;
    const Vec3& key1_position = first ? keys.key1.first_point() : keys.key1.last_point();
    const Vec3& key2_position = first ? keys.key2.first_point() : keys.key2.last_point();
    if (std::optional<Diagnostic> problem =
            check_path_ends(file, file_name, first ? "first" : "last", key1_position, key2_position))
        return *std::move(problem);
    return control_points_from(file, defaults);
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
