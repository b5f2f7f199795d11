#pragma once

#include <string>
#include <string_view>

namespace apcs {

// Blanks that separate fields in APCS's text files: space, tab, CR, VT, FF.
constexpr bool is_field_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// `c` in ASCII lower case; every other byte stays as it is.
constexpr char ascii_lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// `text` in ASCII lower case ("TENSION" → "tension").
inline std::string ascii_lower_case(std::string_view text)
{
    std::string lower(text);
    for (char& c : lower)
        c = ascii_lower(c);
    return lower;
}

// Whether two names or keywords are equal ignoring ASCII case, as DOS compared them.
constexpr bool equals_ignoring_case(std::string_view left, std::string_view right)
{
    if (left.size() != right.size())
        return false;
    for (std::size_t i = 0; i < left.size(); ++i)
        if (ascii_lower(left[i]) != ascii_lower(right[i]))
            return false;
    return true;
}

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
