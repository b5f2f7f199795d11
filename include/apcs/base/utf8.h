#pragma once

#include <string>
#include <string_view>

namespace apcs {

// Splits UTF-8 into code points; malformed bytes become U+FFFD.
std::u32string decode_utf8(std::string_view utf8);

void append_utf8(std::string& text, char32_t code_point);

// How many terminal columns `code_point` takes: 1, 2 for East Asian wide ones (CJK, fullwidth
// forms, most emoji), 0 for combining and other zero-width ones, -1 for control characters. The
// same on every machine: Unicode's widths as the C.UTF-8 locale knows them, whatever the user's
// locale (a wide character counts 1 only where that locale is missing).
int cell_width(char32_t code_point);

} // namespace apcs
