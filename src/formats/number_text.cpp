#include "apcs/formats/number_text.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

namespace apcs {

namespace {

// Whether a well-formed decimal number (not NaN or infinity) has a magnitude below 1, judged
// from its text alone: the power of ten of its first significant digit is negative.
bool is_below_one(std::string_view number)
{
    if (number.starts_with('-') || number.starts_with('+'))
        number.remove_prefix(1);
    const std::size_t exponent_mark = number.find_first_of("eE");
    const std::string_view digits = number.substr(0, exponent_mark);
    const std::size_t point = std::min(digits.find('.'), digits.size());
    const std::size_t first_significant = digits.find_first_of("123456789");
    if (first_significant == std::string_view::npos)
        return true;
    long long power = first_significant < point ? static_cast<long long>(point - first_significant) - 1
                                                : -static_cast<long long>(first_significant - point);
    if (exponent_mark != std::string_view::npos) {
        std::string_view exponent_text = number.substr(exponent_mark + 1);
        const bool negative = exponent_text.starts_with('-');
        if (negative || exponent_text.starts_with('+'))
            exponent_text.remove_prefix(1);
        long long exponent = 0;
        const auto result = std::from_chars(exponent_text.data(), exponent_text.data() + exponent_text.size(), exponent);
        // An exponent this large outweighs any count of digits, so its sign alone decides.
        constexpr long long decisive_exponent = 1'000'000'000'000'000;
        if (result.ec == std::errc::result_out_of_range || exponent > decisive_exponent)
            return negative;
        power += negative ? -exponent : exponent;
    }
    return power < 0;
}

} // namespace

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
    if (error == std::errc::result_out_of_range && end == field.data() + field.size()) {
        // Too large for a double: infinite, so the caller rejects it as such. Too small (below
        // the smallest subnormal, 4.9e-324): zero, as 1e-310 already rounds to a subnormal, so
        // that every tiny magnitude is read the same way.
        const double sign = field.front() == '-' ? -1.0 : 1.0;
        return is_below_one(field) ? sign * 0.0 : sign * std::numeric_limits<double>::infinity();
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

std::string significant_number(double value, int digits)
{
    if (value == 0.0)
        return "0";
    // to_chars ignores the locale: a message never says 11,3.
    std::array<char, 48> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::general,
                                      std::clamp(digits, 1, 17));
    return std::string(buffer.data(), result.ptr);
}

int digits_telling_apart(double a, double b)
{
    constexpr int fewest = 6;
    for (int digits = fewest; digits < 17; ++digits)
        if (a == b || significant_number(a, digits) != significant_number(b, digits))
            return digits;
    return 17;
}

std::pair<std::string, std::string> significant_numbers(double a, double b)
{
    const int digits = digits_telling_apart(a, b);
    return {significant_number(a, digits), significant_number(b, digits)};
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

int decimals_for_size(double size)
{
    if (!(size > 0.0) || !std::isfinite(size))
        return 9;
    const int decimals = 9 - static_cast<int>(std::floor(std::log10(size)));
    if (decimals > 18)
        return -1; // 10^19 does not fit the digits' 64 bits
    return std::max(decimals, 0);
}

namespace {

constexpr char digit_pairs[] = "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
                               "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
                               "8081828384858687888990919293949596979899";

// The decimal digits of `number`, written ending at `end`; returns where they start.
char* digits_ending_at(char* end, std::uint64_t number, int at_least)
{
    char* start = end;
    while (number >= 100 || at_least > 2) {
        start -= 2;
        std::memcpy(start, digit_pairs + (number % 100) * 2, 2);
        number /= 100;
        at_least -= 2;
    }
    if (number >= 10 || at_least == 2) {
        start -= 2;
        std::memcpy(start, digit_pairs + number * 2, 2);
    } else {
        *--start = static_cast<char>('0' + number);
    }
    return start;
}

} // namespace

void append_fixed(std::string& text, double value, int decimals)
{
    static constexpr std::array<double, 19> powers{1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8, 1e9,
                                                   1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};
    if (decimals < 0 || decimals > 18 || !std::isfinite(value)) {
        append_shortest(text, value);
        return;
    }
    const double scaled = std::fabs(value) * powers[static_cast<std::size_t>(decimals)] + 0.5;
    if (scaled >= 9.2e18) {
        append_shortest(text, value);
        return;
    }
    const auto units = static_cast<std::uint64_t>(scaled);
    const auto unit = static_cast<std::uint64_t>(powers[static_cast<std::size_t>(decimals)]);
    std::array<char, 48> buffer{};
    char* const end = buffer.data() + buffer.size();
    char* start = end;
    if (decimals > 0) {
        start = digits_ending_at(end, units % unit, decimals);
        *--start = '.';
    }
    start = digits_ending_at(start, units / unit, 1);
    if (value < 0.0 && units != 0)
        *--start = '-';
    text.append(start, end);
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

namespace {

// Rounded to 2 decimals before printing, so that a value just below 0 shows "0.00", not "-0.00".
double shown_in_two_decimals(double value)
{
    const double shown = std::round(value * 100.0) / 100.0;
    return shown == 0.0 ? 0.0 : shown;
}

} // namespace

std::string format_staff_value(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%+.2f", shown_in_two_decimals(value));
    return text;
}

std::string format_two_decimals(double value)
{
    char text[40];
    std::snprintf(text, sizeof text, "%.2f", shown_in_two_decimals(value));
    return text;
}

} // namespace apcs
