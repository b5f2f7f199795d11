#pragma once

#include "apcs/base/diagnostic.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

// An input file a lesson or an exercise is made for, an INPUT line of a key script's preamble
// (SPEC §3.1, §3.2):
//   INPUT NAME CRC32 XXXXXXXX     (an exercise's: the file's very bytes)
//   INPUT NAME                    (a lesson's: the file is there, a regular file)
// NAME a file of the work folder (no folder part), XXXXXXXX the CRC-32 of its bytes (zlib's, as
// `gzip` and PNG use it; 8 hex digits, any case). A replay refuses to begin when the work folder's
// NAME differs: a session that accepted a path rewrote it, and the exercise's goal could then be
// met before the student types a key. A lesson's input has no checksum, since an earlier lesson of
// the class may have rewritten it: only a wrong or empty folder, where the keys would go into the
// prompts as file names, is refused.
struct ScriptInput {
    std::string name;
    std::optional<std::uint32_t> crc32; // none: a lesson's, only its presence checked
    int line_number = 0; // where the script has it, for FILE:LINE
    bool operator==(const ScriptInput&) const = default;
};

// The input of a line that starts with "INPUT " (the words after it, blank-separated; a ';'
// comment may follow), or "FILE:LINE: expected INPUT NAME [CRC32 XXXXXXXX] (REASON); found '…'".
[[nodiscard]] Expected<ScriptInput> parse_input_line(std::string_view words, const std::string& file_name,
                                                     int line_number);

// The line parse_input_line reads back: "INPUT way1.dat CRC32 1db7d833", or "INPUT way1.dat".
std::string input_line(const ScriptInput& input);

// A CRC-32 as an INPUT line writes it: 8 lower-case hex digits.
std::string crc32_text(std::uint32_t crc32);

} // namespace apcs
