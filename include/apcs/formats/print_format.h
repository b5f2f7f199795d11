#pragma once

#include "apcs/geometry/vec3.h"

#include <span>
#include <string>
#include <string_view>

namespace apcs {

// SPEC §7.4: a section line "# NAME", then one point per line "x y z" with six decimals.
void append_print_section(std::string& text, std::string_view name, std::span<const Vec3> points);
void append_print_point(std::string& text, const Vec3& point);

} // namespace apcs
