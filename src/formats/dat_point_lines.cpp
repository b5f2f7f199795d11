#include "dat_point_lines.h"

#include "apcs/animation/input_limits.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/text_lines.h"

#include <cmath>
#include <cstring>

namespace apcs::dat_lines {

Fields split_fields(std::string_view line)
{
    Fields fields;
    for_each_field(line, [&](std::string_view field) {
        if (fields.count < fields.items.size())
            fields.items[fields.count] = field;
        ++fields.count;
    });
    return fields;
}

ReadPoint read_point(const Fields& fields)
{
    ReadPoint read;
    if (fields.size() != 2 && fields.size() != 3 && fields.size() != 7) {
        read.fault = PointFault::field_count;
        return read;
    }
    std::array<double, 7> values{};
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const std::optional<double> value = parse_number(fields[i]);
        read.field = i;
        if (!value)
            read.fault = PointFault::not_a_number;
        else if (!std::isfinite(*value))
            read.fault = PointFault::not_finite;
        else if (std::abs(*value) > max_dat_magnitude)
            read.fault = PointFault::too_large;
        if (read.fault != PointFault::none)
            return read;
        values[i] = *value;
    }
    read.point.position = {values[0], values[1], values[2]};
    if (fields.size() == 7) {
        // t c b a follow x y z in the staff's order.
        StaffValues staff;
        for (std::size_t i = 0; i < staff_lines.size(); ++i) {
            if (!limits::staff_value.contains(values[3 + i])) {
                read.fault = PointFault::staff_outside;
                read.field = 3 + i;
                return read;
            }
            staff[staff_lines[i]] = values[3 + i];
        }
        read.point.staff = staff;
    }
    return read;
}

ScannedHalf scan_half(std::string_view half, const std::string& file_name, bool first_half, std::size_t expected_points)
{
    ScannedHalf scanned;
    constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
    if (std::memchr(half.data(), '\x1A', half.size()) != nullptr || (!first_half && half.starts_with(byte_order_mark))) {
        scanned.needs_whole_text = true;
        return scanned;
    }
    scanned.points.reserve(expected_points);
    const Expected<void> read = for_each_data_line(half, file_name, [&](int line, std::string_view content) {
        scanned.line_count = line;
        const Fields fields = split_fields(content);
        if (fields.empty())
            return Expected<void>(ok);
        ReadPoint point = read_point(fields);
        if (point.fault == PointFault::none) {
            point.point.line = line;
            scanned.points.push_back(point.point);
        } else {
            scanned.others.push_back({line, content, scanned.points.size()});
        }
        return Expected<void>(ok);
    });
    if (!read)
        scanned.problem = read.error();
    return scanned;
}

} // namespace apcs::dat_lines
