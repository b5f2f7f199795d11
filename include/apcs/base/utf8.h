#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

// Splits UTF-8 into code points; malformed bytes become U+FFFD.
std::u32string decode_utf8(std::string_view utf8);

void append_utf8(std::string& text, char32_t code_point);
// append_utf8 where `text` stays `most_bytes` long at most; whether it did (a character that would
// pass the limit is left out whole).
bool append_utf8_within(std::string& text, char32_t code_point, std::size_t most_bytes);

// How many terminal columns `code_point` takes: 1, 2 for East Asian wide ones (CJK, fullwidth
// forms, most emoji), 0 for combining and other zero-width ones, -1 for control characters. The
// same on every machine: Unicode's widths as the C.UTF-8 locale knows them, whatever the user's
// locale (a wide character counts 1 only where that locale is missing).
int cell_width(char32_t code_point);

// How many terminal columns `utf8` takes: its characters' cell_width, control characters none.
int text_columns(std::string_view utf8);

// `utf8` as it fits `columns` terminal columns: whole when it does, else its first characters that
// leave room for "..." after them (a wide character that would straddle the edge left out whole).
std::string fitted_to_columns(std::string_view utf8, int columns);

// The first character of `utf8` that a terminal would obey rather than show: a C0 control but tab,
// DEL, or a C1 control (U+0080-U+009F, or a stray byte 0x80-0x9F), or a bidi control that would
// reorder what is shown around it (U+202A-U+202E, U+2066-U+2069, U+200E, U+200F, U+061C), named
// for a message ("\x1B", "U+009B", "U+202E"); nullopt when there is none. Text from shared files
// (captions, scene names) is refused with it, never echoed.
std::optional<std::string> first_control_character(std::string_view utf8);

// `text` as it may be printed to a terminal or a report: each character first_control_character
// would name is written as that name ("esc\x1B]0;PWN\x07.keys"), every byte that is not part of
// valid UTF-8 as \xNN, the rest as it is (tabs, accents, CJK). Every name of a file or a folder
// that APCS prints (messages, lists of files written, grade's CSV) goes through it.
std::string escape_controls(std::string_view text);

} // namespace apcs
