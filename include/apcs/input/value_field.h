#pragma once

#include <string>
#include <string_view>

namespace apcs {

// The field "=" opens on the message line of a staff line: the animator types the value instead of
// stepping to it. Every printable key is typed text; Enter reads it as a number.
class ValueField {
public:
    // A printable key typed ('=' typed on an empty field is ignored: it is the key that opened it).
    void type(char32_t character);
    // Backspace: the last character erased.
    void erase();
    // Enter: true when the text is a number (value() then holds it); else the problem says why,
    // quoting the text, and the field stays open and empty. Esc closes the field: its owner drops it.
    bool submit();
    // Whether Enter now would set the value: the text is a finite number.
    bool holds_number() const;
    // The number read by the Enter whose submit() was true, clamped to [-1, 1].
    double value() const { return m_value; }
    // Whether the number typed lay outside [-1, 1] and was clamped.
    bool clamped() const { return m_clamped; }
    // The message line: "TENSION = 0.35_  a value from -1 to 1", or why the last Enter was refused.
    std::string message(std::string_view line_name) const;

private:
    std::string m_text;
    std::string m_problem;
    double m_value = 0.0;
    bool m_clamped = false;
};

} // namespace apcs
