#include "apcs/formats/print_format.h"

#include "apcs/formats/number_text.h"

namespace apcs {

void append_print_point(std::string& text, const Vec3& point)
{
    text += fixed_six(point.x);
    text += ' ';
    text += fixed_six(point.y);
    text += ' ';
    text += fixed_six(point.z);
    text += '\n';
}

void append_print_section(std::string& text, std::string_view name, std::span<const Vec3> points)
{
    text += "# ";
    text += name;
    text += '\n';
    for (const Vec3& point : points)
        append_print_point(text, point);
}

} // namespace apcs
