#include "apcs/formats/path_files.h"

#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace apcs {

std::string path_file_name(std::size_t point_number) { return "ani" + std::to_string(point_number) + ".dat"; }

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

int inbetween_decimals(std::span<const Vec3> key1, std::span<const Vec3> key2)
{
    double size = 0.0;
    for (const std::span<const Vec3> key : {key1, key2})
        for (const Vec3& point : key)
            size = std::max({size, std::abs(point.x), std::abs(point.y), std::abs(point.z)});
    return decimals_for_size(size);
}

int inbetween_decimals(const FrameSequence& frames)
{
    if (frames.frame_count() == 0)
        return decimals_for_size(0.0);
    return inbetween_decimals(frames.frame(0), frames.frame(frames.frame_count() - 1));
}

std::string inbetween_heading(std::size_t number, std::size_t count)
{
    return "; APCS in-between " + std::to_string(number) + " of " + std::to_string(count) + "\n";
}

NamedText inbetween_file(const FrameSequence& frames, const Graphic& structure, std::size_t number)
{
    return {inbetween_file_name(number),
            inbetween_heading(number, inbetween_count(frames)) +
                format_graphic(structure, frames.frame(number), inbetween_decimals(frames))};
}

std::string describe_point(const Vec3& point, int digits)
{
    return "(" + significant_number(point.x, digits) + ", " + significant_number(point.y, digits) + ", " +
           significant_number(point.z, digits) + ")";
}

std::pair<std::string, std::string> describe_points(const Vec3& a, const Vec3& b)
{
    // The points read apart once one coordinate does: the fewest digits of those that differ.
    int digits = 17;
    for (const auto& [from_a, from_b] : {std::pair{a.x, b.x}, std::pair{a.y, b.y}, std::pair{a.z, b.z}})
        if (from_a != from_b)
            digits = std::min(digits, digits_telling_apart(from_a, from_b));
    if (a == b)
        digits = 6;
    return {describe_point(a, digits), describe_point(b, digits)};
}

namespace {

bool same_place(const Vec3& a, const Vec3& b)
{
    const double scale = std::max({1.0, std::abs(a.x), std::abs(a.y), std::abs(a.z)});
    return distance(a, b) <= 1e-6 * scale;
}

} // namespace

Expected<void> check_path_ends(const DatFile& path, const std::string& file_name, const std::string& which,
                               const Vec3& key1_position, const Vec3& key2_position)
{
    if (path.parts.empty() || path.parts.front().points.empty())
        return Diagnostic{file_name, 0, "has no control points"};
    const DatPoint& start = path.parts.front().points.front();
    const DatPoint& end = path.parts.back().points.back();
    if (!same_place(start.position, key1_position)) {
        const auto [path_text, key_text] = describe_points(start.position, key1_position);
        return Diagnostic{file_name, start.line,
                          "the path starts at " + path_text + "; expected the " + which +
                              " graphic point's KEY1 position " + key_text};
    }
    if (!same_place(end.position, key2_position)) {
        const auto [path_text, key_text] = describe_points(end.position, key2_position);
        return Diagnostic{file_name, end.line,
                          "the path ends at " + path_text + "; expected the " + which +
                              " graphic point's KEY2 position " + key_text};
    }
    return ok;
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
    if (Expected<void> ends = check_path_ends(file, file_name, first ? "first" : "last", key1_position, key2_position);
        !ends)
        return ends.error();
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

namespace {

// The text's lines without their line ends; a final line end starts no further line.
std::vector<std::string_view> lines_of(std::string_view text)
{
    std::vector<std::string_view> lines;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        std::string_view line = text.substr(0, end);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        lines.push_back(line);
        text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
    return lines;
}

} // namespace

std::string format_path_file(std::string_view original_text, const DatFile& original, const ControlPoints& points,
                             std::span<const std::size_t> origins, std::optional<EndSlopes> slopes)
{
    const std::vector<std::string_view> lines = lines_of(original_text);
    const std::string line_end = original_text.find("\r\n") != std::string_view::npos ? "\r\n" : "\n";
    std::vector<std::size_t> point_lines; // from 1, each original point's
    std::vector<bool> is_point_line(lines.size() + 1, false);
    for (const DatPart& part : original.parts)
        for (const DatPoint& point : part.points) {
            point_lines.push_back(static_cast<std::size_t>(point.line));
            if (static_cast<std::size_t>(point.line) < is_point_line.size())
                is_point_line[static_cast<std::size_t>(point.line)] = true;
        }
    std::string text;
    text.reserve(original_text.size() + points.size() * 16);
    std::size_t next_line = 1; // the first line not written yet
    // The other lines before `line` (comments, PART lines); a deleted point's own line goes, and
    // an old SLOPES line when new slopes are written.
    const auto replaced = [&](std::string_view content) {
        bool first_field = true;
        bool is_slopes = false;
        for_each_field(content, [&](std::string_view field) {
            is_slopes = is_slopes || (first_field && equals_ignoring_case(field, "SLOPES"));
            first_field = false;
        });
        return slopes && is_slopes;
    };
    const auto copy_lines_before = [&](std::size_t line) {
        for (; next_line < line && next_line <= lines.size(); ++next_line)
            if (!is_point_line[next_line] && !replaced(lines[next_line - 1]))
                text.append(lines[next_line - 1]).append(line_end);
    };
    for (std::size_t j = 0; j < points.size(); ++j) {
        std::string_view comment; // a comment after the numbers on the point's own line
        if (j < origins.size() && origins[j] < point_lines.size()) {
            const std::size_t line = point_lines[origins[j]];
            copy_lines_before(line);
            next_line = line + 1;
            if (line >= 1 && line <= lines.size() && lines[line - 1].find(';') != std::string_view::npos)
                comment = lines[line - 1].substr(lines[line - 1].find(';'));
        }
        if (j == 0 && slopes)
            text.append(slopes_line(*slopes)).append(line_end);
        append_point_line(text, points[j].position, points[j].staff);
        if (!comment.empty())
            text.append(" ").append(comment);
        text += line_end;
    }
    copy_lines_before(lines.size() + 1);
    return text;
}

} // namespace apcs
