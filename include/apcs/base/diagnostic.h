#pragma once

#include "apcs/base/utf8.h"

#include <string>
#include <utility>
#include <variant>

namespace apcs {

// What went wrong with an input, where: "FILE:LINE: message", or "FILE: message" when no line
// applies (line 0).
struct Diagnostic {
    std::string file;
    int line = 0;
    std::string message;

    // Printed to a terminal or a report, so a name that carries control characters (a file named
    // $'a\e]0;x\a.keys') shows them escaped ("a\x1B]0;x\x07.keys"), never obeyed (escape_controls).
    std::string to_string() const
    {
        std::string text = file;
        if (line > 0)
            text += ":" + std::to_string(line);
        return escape_controls(text + ": " + message);
    }
};

// A value or the diagnostic that explains why there is none (g++ 12 has no std::expected).
// [[nodiscard]]: a function that returns one must not have its problem dropped unread.
template <typename T>
class [[nodiscard]] Expected {
public:
    Expected(T value) : m_content(std::move(value)) {}
    Expected(Diagnostic error) : m_content(std::move(error)) {}

    bool has_value() const { return std::holds_alternative<T>(m_content); }
    explicit operator bool() const { return has_value(); }
    T& value() { return std::get<T>(m_content); }
    const T& value() const { return std::get<T>(m_content); }
    T& operator*() { return value(); }
    const T& operator*() const { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    const Diagnostic& error() const { return std::get<Diagnostic>(m_content); }

private:
    std::variant<T, Diagnostic> m_content;
};

// The value of a success that has nothing to return: `return ok;`. (Not `success`: that is an
// ExitStatus.)
struct Ok {};
inline constexpr Ok ok{};

// Success, or the diagnostic that explains the failure: what a check or a write returns.
//     Expected<void> write_x(…) { if (…) return Diagnostic{…}; return ok; }
//     if (const Expected<void> written = write_x(…); !written) report(written.error());
template <>
class [[nodiscard]] Expected<void> {
public:
    Expected(Ok) {}
    Expected(Diagnostic error) : m_content(std::move(error)) {}

    bool has_value() const { return std::holds_alternative<Ok>(m_content); }
    explicit operator bool() const { return has_value(); }
    const Diagnostic& error() const { return std::get<Diagnostic>(m_content); }

private:
    std::variant<Ok, Diagnostic> m_content;
};

} // namespace apcs
