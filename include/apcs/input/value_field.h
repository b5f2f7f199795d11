#pragma once

#include "apcs/input/command.h"

#include <string>
#include <string_view>

namespace apcs {

// The field "=" opens on the message line of a staff line: the animator types the value instead of
// stepping to it. Every printable key is typed text; Enter reads it as a number.
class ValueField {
public:
    enum class Outcome { editing, set, closed };

    // Typing, Backspace, Enter (a number sets; anything else says why, quoting the text, and keeps
    // the field open and empty), Esc (ClearLine) closes. '=' typed on an empty field is ignored: it
    // is the key that opened it.
    Outcome update(const Command& command);
    // The number read by the Enter that gave Outcome::set, clamped to [-1, 1].
    double value() const { return m_value; }
    // Whether the number typed lay outside [-1, 1] and was clamped.
    bool clamped() const { return m_clamped; }
    // The message line: "TENSION = 0.35_  a value from -1 to 1", or why the last Enter was refused.
    std::string message(std::string_view line_name) const;

private:
    // Enter: the text read as a number, or why not.
    Outcome submit();

    std::string m_text;
    std::string m_problem;
    double m_value = 0.0;
    bool m_clamped = false;
};

} // namespace apcs
