#include "apcs/base/utf8.h"

#include <algorithm>
#include <cstdio>
#include <locale.h>
#include <wchar.h>

namespace apcs {

std::u32string decode_utf8(std::string_view utf8)
{
    std::u32string decoded;
    decoded.reserve(utf8.size());
    for (std::size_t i = 0; i < utf8.size();) {
        const auto lead = static_cast<unsigned char>(utf8[i]);
        const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + static_cast<std::size_t>(length) > utf8.size()) {
            decoded.push_back(U'\uFFFD');
            ++i;
            continue;
        }
        char32_t value = length == 1 ? lead : static_cast<char32_t>(lead & (0x7F >> length));
        bool valid = true;
        for (int k = 1; k < length; ++k) {
            const auto next = static_cast<unsigned char>(utf8[i + static_cast<std::size_t>(k)]);
            valid = valid && (next >> 6) == 0x2;
            value = (value << 6) | (next & 0x3F);
        }
        decoded.push_back(valid ? value : U'\uFFFD');
        i += valid ? static_cast<std::size_t>(length) : 1;
    }
    return decoded;
}

int text_columns(std::string_view utf8)
{
    int columns = 0;
    for (const char32_t character : decode_utf8(utf8))
        columns += std::max(cell_width(character), 0);
    return columns;
}

std::string fitted_to_columns(std::string_view utf8, int columns)
{
    if (text_columns(utf8) <= columns)
        return std::string(utf8);
    constexpr std::string_view cut_mark = "...";
    const int room = columns - static_cast<int>(cut_mark.size());
    std::string fitted;
    int taken = 0;
    for (const char32_t character : decode_utf8(utf8)) {
        taken += std::max(cell_width(character), 0);
        if (taken > room)
            break;
        append_utf8(fitted, character);
    }
    return room < 0 ? std::string(cut_mark.substr(0, static_cast<std::size_t>(std::max(columns, 0))))
                    : fitted + std::string(cut_mark);
}

int cell_width(char32_t code_point)
{
    if (code_point >= 0x20 && code_point < 0x7F)
        return 1;
    // A locale of its own, used on this thread only for the call: the user's locale and every
    // other thread are left as they are.
    static const locale_t utf8 = ::newlocale(LC_CTYPE_MASK, "C.UTF-8", static_cast<locale_t>(nullptr));
    if (utf8 == static_cast<locale_t>(nullptr))
        return code_point < 0x20 || (code_point >= 0x7F && code_point < 0xA0) ? -1 : 1;
    const locale_t previous = ::uselocale(utf8);
    const int width = ::wcwidth(static_cast<wchar_t>(code_point));
    ::uselocale(previous);
    return width;
}

void append_utf8(std::string& text, char32_t code_point)
{
    if (code_point < 0x80) {
        text += static_cast<char>(code_point);
    } else if (code_point < 0x800) {
        text += static_cast<char>(0xC0 | (code_point >> 6));
        text += static_cast<char>(0x80 | (code_point & 0x3F));
    } else if (code_point < 0x10000) {
        text += static_cast<char>(0xE0 | (code_point >> 12));
        text += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
        text += static_cast<char>(0x80 | (code_point & 0x3F));
    } else {
        text += static_cast<char>(0xF0 | (code_point >> 18));
        text += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
        text += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
        text += static_cast<char>(0x80 | (code_point & 0x3F));
    }
}

namespace {

// The bytes of the UTF-8 sequence that starts at `at`, or 0 when none does (a stray byte).
std::size_t sequence_length(std::string_view utf8, std::size_t at)
{
    const auto lead = static_cast<unsigned char>(utf8[at]);
    const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
    if (length == 0 || at + length > utf8.size())
        return 0;
    for (std::size_t i = at + 1; i < at + length; ++i)
        if ((static_cast<unsigned char>(utf8[i]) & 0xC0) != 0x80)
            return 0;
    return length;
}

} // namespace

namespace {

std::string hex_byte(unsigned value)
{
    constexpr std::string_view digits = "0123456789ABCDEF";
    return std::string("\\x") + digits[(value >> 4) & 0xF] + digits[value & 0xF];
}

// How a message names `character` when a terminal would obey it rather than show it ("\x1B",
// "U+009B"), or when it would reorder the text shown around it: a bidi control (U+202E makes
// "txt.exe" of "exe.txt"); nullopt for a character that is shown as it is.
std::optional<std::string> control_name(char32_t character)
{
    const auto code = static_cast<unsigned>(character);
    if (character < 0x20 && character != U'\t')
        return hex_byte(code);
    if (character == 0x7F)
        return hex_byte(code);
    if (character >= 0x80 && character <= 0x9F)
        return "U+00" + hex_byte(code).substr(2);
    const bool bidi = character == 0x061C || character == 0x200E || character == 0x200F ||
                      (character >= 0x202A && character <= 0x202E) || (character >= 0x2066 && character <= 0x2069);
    if (!bidi)
        return std::nullopt;
    // Room for any unsigned value: GCC's -Wformat-truncation judges the type, not the range above.
    char name[16];
    std::snprintf(name, sizeof name, "U+%04X", code);
    return name;
}

char32_t character_at(std::string_view utf8, std::size_t at, std::size_t length)
{
    const std::u32string decoded = decode_utf8(utf8.substr(at, length));
    return decoded.empty() ? U'\uFFFD' : decoded.front();
}

} // namespace

std::optional<std::string> first_control_character(std::string_view utf8)
{
    for (std::size_t at = 0; at < utf8.size();) {
        const std::size_t length = sequence_length(utf8, at);
        const auto byte = static_cast<unsigned char>(utf8[at]);
        // A stray byte 0x80-0x9F is a C1 control to a terminal in an 8-bit mode (0x9B: CSI).
        if (length == 0) {
            if (byte >= 0x80 && byte <= 0x9F)
                return hex_byte(byte);
            ++at;
            continue;
        }
        if (std::optional<std::string> name = control_name(character_at(utf8, at, length)))
            return name;
        at += length;
    }
    return std::nullopt;
}

std::string escape_controls(std::string_view text)
{
    std::string shown;
    shown.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = sequence_length(text, at);
        // Every stray byte, not only those a terminal obeys: what it shows for one is a guess.
        if (length == 0) {
            shown += hex_byte(static_cast<unsigned char>(text[at++]));
            continue;
        }
        const std::optional<std::string> name = control_name(character_at(text, at, length));
        shown += name ? std::string_view(*name) : text.substr(at, length);
        at += length;
    }
    return shown;
}

bool append_utf8_within(std::string& text, char32_t code_point, std::size_t most_bytes)
{
    const std::size_t before = text.size();
    append_utf8(text, code_point);
    if (text.size() <= most_bytes)
        return true;
    text.resize(before);
    return false;
}

} // namespace apcs
