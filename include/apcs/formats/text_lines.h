#pragma once

#include "apcs/formats/diagnostic.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

inline constexpr std::size_t max_text_line_bytes = 4096;

// What a data line handler says: nothing (go on) or the problem that ends the reading.
using DataLineHandler = std::function<std::optional<Diagnostic>(int line_number, std::string_view content)>;

// The lexical rules that .dat and .scn files share (SPEC §2.1): a UTF-8 byte-order mark is
// skipped; a Ctrl-Z may end the file (only line ends and blanks after it); lines end with LF,
// CR LF or a lone CR; a line holds at most max_text_line_bytes bytes and no NUL; ';' or '#'
// starts a comment that runs to the line's end. `handle` gets every line's content before its
// comment (blank lines too), numbered from 1; the first problem, its own or the handler's, ends
// the reading and is returned as "FILE:LINE: message" for `file_name`.
[[nodiscard]] std::optional<Diagnostic> for_each_data_line(std::string_view text, const std::string& file_name,
                                                           const DataLineHandler& handle);

} // namespace apcs
