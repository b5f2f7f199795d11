#pragma once

#include "apcs/formats/dat_file.h"
#include "apcs/formats/diagnostic.h"
#include "apcs/formats/key_file_guard.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace apcs {

// The file a user means by `name`: the name itself when it exists, else the one entry of its
// folder whose name matches case-insensitively (as DOS did: KEY1.DAT finds key1.dat), else `name`.
std::filesystem::path resolve_input_path(const std::filesystem::path& name);

// Whole text of a file, resolved as above. Errors name the file as the user typed it. Only a
// regular file (or a symbolic link to one) is read: a directory, a FIFO, a device or a socket is
// refused without being opened, so that a FIFO nobody writes never hangs the program.
Expected<std::string> read_text_file(const std::filesystem::path& name);

Expected<DatFile> read_dat_file(const std::filesystem::path& name, std::size_t minimum_points = 2);

// A key frame: a .dat file of at least two points, as a graphic.
Expected<Graphic> read_key_frame(const std::filesystem::path& name);

enum class WriteOutcome { created, replaced, unchanged };

struct WriteResult {
    WriteOutcome outcome = WriteOutcome::created;
    // Where the previous content was kept when the file was replaced (NAME.bak), else empty.
    std::filesystem::path backup;
};

// Writes `content` to `target` atomically: a temporary file in the same folder, flushed, then
// renamed over the target, so a reader never sees half a file. An existing target whose content
// differs is first kept as the same name with the extension .bak (way1.dat → way1.bak, replacing an
// older .bak); identical content leaves the file untouched. A replaced file keeps its mode (and
// its owner and group where the user may set them); a new one is 0644. Only regular files are
// replaced: a symbolic link to a regular file is written through (the file it names is replaced in
// its own folder, its .bak beside it, the link stays); a directory, a FIFO, a device, a socket, a
// link to one or a dangling link is refused, and so is a read-only file (no write permission for
// the user; for root, no write bit at all). A refusal, a missing folder, a full disk or a failed
// rename is reported and leaves every file as it was. When NAME.bak is one of `inputs` (a key
// file of the run), the old file is kept as NAME.b01 (or the first of .b02 … .b99 that is free)
// instead, so that a backup never replaces an input; WriteResult::backup names it.
Expected<WriteResult> write_file_atomically(const std::filesystem::path& target, std::string_view content,
                                            const KeyFileGuard* inputs = nullptr);

// NAME.ext → NAME.bak in the same folder; NAME.b01 … NAME.b99 when NAME.bak is one of `inputs`
// (the first of those that is neither an input nor an existing file; NAME.b99 when all exist;
// empty when all are inputs).
std::filesystem::path backup_path_for(const std::filesystem::path& target, const KeyFileGuard* inputs = nullptr);

} // namespace apcs
