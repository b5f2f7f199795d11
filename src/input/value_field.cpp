#include "apcs/input/value_field.h"

#include "apcs/animation/input_limits.h"
#include "apcs/base/utf8.h"
#include "apcs/formats/number_text.h"
#include "apcs/raster/cell_grid.h"

#include <algorithm>
#include <cmath>

namespace apcs {

namespace {

// Backspace takes the last character, not its last byte.
void erase_last_character(std::string& text)
{
    while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
        text.pop_back();
    if (!text.empty())
        text.pop_back();
}

// Wider than any number worth typing; the message line stays one line.
constexpr std::size_t longest_text = 24;

// Why `text` is no value: a number with a decimal comma (a German keyboard's 0,5) is shown with
// its point, since numbers have a '.' in every locale.
std::string refusal(const std::string& text)
{
    std::string with_point = text;
    std::ranges::replace(with_point, ',', '.');
    if (with_point != text && parse_number(with_point))
        return "'" + text + "' is not a number: the decimal point is '.', type " + with_point;
    return "'" + text + "' is not a number: type a value from -1 to 1, e.g. 0.35";
}

} // namespace

// '=' again on an empty field is the key that opened it, not text.
void ValueField::type(char32_t character)
{
    m_problem.clear();
    if (m_text.empty() && character == U'=')
        return;
    append_utf8_within(m_text, character, longest_text);
}

void ValueField::erase()
{
    m_problem.clear();
    erase_last_character(m_text);
}

bool ValueField::holds_number() const
{
    const std::optional<double> number = parse_number(m_text);
    return number && std::isfinite(*number);
}

bool ValueField::submit()
{
    if (m_text.empty()) {
        m_problem = "Type a value from -1 to 1 first, then Enter (Esc closes the field)";
        return false;
    }
    const std::optional<double> number = parse_number(m_text);
    if (!number || !std::isfinite(*number)) {
        // The text is said in the problem and taken away: what is typed next starts afresh, as
        // the field shows it once the problem has been read.
        m_problem = refusal(m_text);
        m_text.clear();
        return false;
    }
    m_value = limits::staff_value.clamp(*number);
    m_clamped = m_value != *number;
    return true;
}

std::string ValueField::message(std::string_view line_name) const
{
    if (!m_problem.empty())
        return m_problem;
    return std::string(line_name) + " = " + m_text + "_  a value from -1 to 1, Enter sets it";
}

} // namespace apcs
