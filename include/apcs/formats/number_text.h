#pragma once

#include "apcs/animation/input_limits.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <string_view>

namespace apcs {

// A decimal or exponent number, optionally signed (a leading '+' is allowed); the whole field
// must be the number. NaN and infinities parse (the caller rejects them with its own message).
std::optional<double> parse_number(std::string_view field);

// A whole number of decimal digits, optionally with a leading '+'; values beyond size_t's range
// come back as SIZE_MAX so that the caller's limit check reports them.
std::optional<std::size_t> parse_count_value(std::string_view field);

// The shortest decimal text that reads back as exactly `value`; −0 is written as 0.
std::string shortest_number(double value);

// `value` with `digits` significant digits (1 to 17, 6 unless said) for a message: '.' as the
// decimal point whatever the locale, −0 as 0, no trailing zeros: "11.3", not 11.300000000000001.
std::string significant_number(double value, int digits = 6);

// The fewest significant digits, six or more, at which `a` and `b` read apart (six when they are
// equal): a message comparing two numbers never shows two different ones alike.
int digits_telling_apart(double a, double b);

// `a` and `b` in digits_telling_apart's digits: a distance and its limit, two TOLERANCE values.
std::pair<std::string, std::string> significant_numbers(double a, double b);

// Appends shortest_number(value) to `text` without a temporary string.
void append_shortest(std::string& text, double value);

// The decimals that keep every coordinate of a drawing within 0.5e-9 × `size` when read back
// (`size`: its largest absolute coordinate): 9 − ⌊log10 size⌋, at least 0 (9 for size 0). Below
// 1e-9 no fixed count does: −1, meaning the shortest form.
int decimals_for_size(double size);

// `value` with exactly `decimals` decimals (printf's "%.*f", rounded half away from zero), −0 as
// 0; the shortest form when `decimals` is −1, when the value is not finite or when its digits
// would pass 19 (|value| · 10^decimals ≥ 2^63). Several times faster than the shortest form.
void append_fixed(std::string& text, double value, int decimals);

// "[MIN, MAX]" with the shortest numbers, as messages and help texts write a range: "[-1, 1]".
std::string range_text(const limits::Range& range);

// `value` with exactly six decimals (SPEC §7.4); −0.000000 is written as 0.000000.
std::string fixed_six(double value);

// "+0.05", "-1.00": a staff value as the staff shows it (also the --tree of a scene, the depth of
// the waypoint editor), never "-0.00".
std::string format_staff_value(double value);

// "0.05", "-1.00": a number of the message line, never "-0.00".
std::string format_two_decimals(double value);

// A field for an error message: in single quotes, at most 24 characters, control and non-ASCII
// bytes as \xNN.
std::string quote_field(std::string_view field);

} // namespace apcs
