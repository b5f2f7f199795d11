#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/script_input.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace apcs {

// The CRC-32 of a file's bytes (zlib's crc32). Only a regular file is read: a symbolic link, a
// FIFO, a directory or a device is refused without being read ("is a symbolic link"), so that a
// FIFO nobody writes never hangs the check. The problem's message has no file name: the caller
// names the file as its user knows it.
Expected<std::uint32_t> file_crc32(const std::filesystem::path& file);

// ok when each of an exercise's `inputs` is, in `folder`, the file the exercise was made for (and
// each of a lesson's is there, a regular file); else "SCRIPT:LINE: way1.dat differs from the
// exercise's (CRC-32 …, expected …): …; copy the exercise's files into the work folder again", or
// the same for a missing file, a link or a FIFO.
// A symbolic link is refused even to the right content: the session rewrites an input when a path
// is accepted, and would write through the link into the teacher's copy. Nothing is written.
// `folder` is the session's work folder, or (apcs grade) the exercise's own: a message names it as
// its user knows it.
enum class InputFolder { work, exercise };
[[nodiscard]] Expected<void> check_script_inputs(const std::vector<ScriptInput>& inputs,
                                                 const std::filesystem::path& folder, const std::string& script_name,
                                                 InputFolder role = InputFolder::work);

} // namespace apcs
