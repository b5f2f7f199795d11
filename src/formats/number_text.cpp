#include "apcs/formats/number_text.h"

#include <array>
#include <charconv>
#include <cstdint>
#include <limits>

namespace apcs {

std::optional<double> parse_number(std::string_view field)
{
    if (field.starts_with('+')) {
        field.remove_prefix(1);
        if (field.starts_with('+') || field.starts_with('-'))
            return std::nullopt;
    }
    if (field.empty())
        return std::nullopt;
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error == std::errc::result_out_of_range) {
        // Magnitudes beyond double's range: report them as infinite so they are rejected as such.
        return field.front() == '-' ? -std::numeric_limits<double>::infinity()
                                    : std::numeric_limits<double>::infinity();
    }
    if (error != std::errc{} || end != field.data() + field.size())
        return std::nullopt;
    return value;
}

std::optional<std::size_t> parse_count_value(std::string_view field)
{
    if (field.starts_with('+'))
        field.remove_prefix(1);
    if (field.empty())
        return std::nullopt;
    std::size_t value = 0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (end != field.data() + field.size())
        return std::nullopt;
    if (error == std::errc::result_out_of_range)
        return std::numeric_limits<std::size_t>::max();
    if (error != std::errc{})
        return std::nullopt;
    return value;
}

std::string shortest_number(double value)
{
    if (value == 0.0)
        return "0";
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

void append_shortest(std::string& text, double value)
{
    if (value == 0.0) {
        text += '0';
        return;
    }
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    text.append(buffer.data(), result.ptr);
}

std::string range_text(const limits::Range& range)
{
    return "[" + shortest_number(range.min) + ", " + shortest_number(range.max) + "]";
}

std::string fixed_six(double value)
{
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed, 6);
    std::string text(buffer.data(), result.ptr);
    if (text == "-0.000000")
        return "0.000000";
    return text;
}

std::string quote_field(std::string_view field)
{
    constexpr std::size_t longest = 24;
    std::string text = "'";
    for (std::size_t i = 0; i < field.size() && i < longest; ++i) {
        const auto byte = static_cast<unsigned char>(field[i]);
        if (byte < 0x20 || byte >= 0x7F) {
            constexpr std::string_view digits = "0123456789ABCDEF";
            text += "\\x";
            text += digits[byte >> 4];
            text += digits[byte & 0xF];
        } else {
            text += static_cast<char>(byte);
        }
    }
    if (field.size() > longest)
        text += "...";
    return text + "'";
}

} // namespace apcs
