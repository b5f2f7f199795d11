#pragma once

#include <string_view>

namespace apcs {

// Blanks that separate fields in APCS's text files: space, tab, CR, VT, FF.
constexpr bool is_field_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Calls visit(field) for every blank-separated field of `line`, in order; nothing is allocated.
template <typename Visit>
void for_each_field(std::string_view line, Visit visit)
{
    std::size_t position = 0;
    while (position < line.size()) {
        while (position < line.size() && is_field_blank(line[position]))
            ++position;
        const std::size_t start = position;
        while (position < line.size() && !is_field_blank(line[position]))
            ++position;
        if (position > start)
            visit(line.substr(start, position - start));
    }
}

} // namespace apcs
