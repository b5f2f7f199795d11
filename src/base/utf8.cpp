#include "apcs/base/utf8.h"

#include <algorithm>
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

std::optional<std::string> first_control_character(std::string_view utf8)
{
    constexpr std::string_view digits = "0123456789ABCDEF";
    const auto hex = [&](unsigned value) { return std::string(1, digits[value >> 4]) + digits[value & 0xF]; };
    for (std::size_t at = 0; at < utf8.size();) {
        const std::size_t length = sequence_length(utf8, at);
        const auto byte = static_cast<unsigned char>(utf8[at]);
        // A stray byte 0x80-0x9F is a C1 control to a terminal in an 8-bit mode (0x9B: CSI).
        if (length == 0) {
            if (byte >= 0x80 && byte <= 0x9F)
                return "\\x" + hex(byte);
            ++at;
            continue;
        }
        const std::u32string decoded = decode_utf8(utf8.substr(at, length));
        const char32_t character = decoded.empty() ? U'\uFFFD' : decoded.front();
        at += length;
        if (character == U'\t' || (character >= 0x20 && character < 0x7F) || character > 0x9F)
            continue;
        const auto code = static_cast<unsigned>(character);
        return (character < 0x80 ? "\\x" : "U+00") + hex(code);
    }
    return std::nullopt;
}

} // namespace apcs
