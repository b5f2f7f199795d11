#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/key_file_guard.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// The folder an --out names, made when it is not there (one level, with the umask's mode, as
// mkdir makes it); its parent must be a folder. ok for an existing folder (or a link to one); else
// "FOLDER: is not a folder; expected a folder for PURPOSE" (a file of that name) or "FOLDER:
// cannot be made: PARENT is not a folder (--out makes one level, not its parents)".
Expected<void> make_output_folder(const std::filesystem::path& folder, std::string_view purpose);

// Told after each file of a run is written: how many are written so far, and of how many. Called
// from the writing threads, one call at a time per file; it must be safe to call from any thread.
using WriteProgress = std::function<void(std::size_t written, std::size_t count)>;

// A run of files written into one folder (in-betweens inb001.dat …, scene frames frm000.dat …):
// file k (0 … count−1) is named name_of(k) and its content made by writer_of(k) chunk by chunk as
// it is written. Every target is checked against `guard` before any file is written (a guarded
// one stops the whole writing); each file is written atomically, the files spread over the cores,
// and one barrier (flush_file_system) puts them all on the disk before this returns, not one
// flush per file. Before any is written, every target must be replaceable (check_replaceable: a
// folder named inb002.dat, a read-only inb010.dat or an inb003.bak that cannot be replaced stops
// the run before inb001.dat is written) and the folder's free space, in its blocks, must hold the
// files (estimated_files_bytes, room_for_files). A write that fails after that says how many of
// the run were written and which were not. Returns the files written, or the first
// problem: a `folder` that is not a folder and cannot be made (make_output_folder), a guarded
// or unwritable target, too little space, or a file that could not be written. `progress`, when
// given, is told of each file written.
[[nodiscard]] Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<void(std::size_t, const ContentSink&)>& writer_of, const KeyFileGuard& guard,
                     std::string_view purpose, const WriteProgress& progress = {});

// The bytes `count` files made by writer_of take on a file system of `block_bytes` blocks (each
// file rounded up to whole blocks), estimated from five spread over the run (the first, at a
// quarter, half and three quarters, the last), each made once and counted, nothing kept: their
// mean for every file. The middle frames of a move carry more digits than its ends, so when the
// five say less than 8 MiB in all every file is measured instead.
std::uintmax_t estimated_files_bytes(std::size_t count,
                                     const std::function<void(std::size_t, const ContentSink&)>& writer_of,
                                     std::uintmax_t block_bytes = 1);

// ok when `needed` bytes fit in `free_bytes`; else "FOLDER: PURPOSE need about 52 GiB (100000
// files); the folder has 3.1 GiB free".
Expected<void> room_for_files(std::uintmax_t needed, std::uintmax_t free_bytes, std::size_t count,
                              const std::filesystem::path& folder, std::string_view purpose);

// The same with each file's whole text made by content_of(k) when it is written, so that one
// file's text per core is in memory at once.
[[nodiscard]] Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<std::string(std::size_t)>& content_of, const KeyFileGuard& guard,
                     std::string_view purpose, const WriteProgress& progress = {});

// Of `names`, those of the numbered set PREFIX + digits + SUFFIX (at least three digits, any case,
// as DOS wrote them: "frm013.dat", "INB0012.DAT") that `keep` takes (given the number and the
// name), in number order, a number's names in name order.
[[nodiscard]] std::vector<std::string>
numbered_names(std::span<const std::string> names, std::string_view prefix, std::string_view suffix,
               const std::function<bool(std::size_t number, const std::string& name)>& keep);

// The names of `folder`'s entries, in the order the folder lists them; none when it cannot be read.
[[nodiscard]] std::vector<std::string> file_names_in(const std::filesystem::path& folder);

// Of `names` (a folder's file names), the files of the numbered set PREFIX + digits + SUFFIX (at
// least three digits, any case, as DOS wrote them: frm000.dat, FRM0012.DAT) that are not among
// `written` (the names a run has just written), in number order, a number's names in name order:
// what an earlier run left, with more files or with its numbers at another width (frm000.dat beside
// a run of frm0000.dat ... frm1000.dat). They are never deleted, only pointed out
// (earlier_inbetweens_note words them).
[[nodiscard]] std::vector<std::string> earlier_numbered_files(std::span<const std::string> names,
                                                              std::string_view prefix, std::string_view suffix,
                                                              std::span<const std::string> written);

// earlier_numbered_files for the files of `folder`.
[[nodiscard]] std::vector<std::string> earlier_numbered_files(const std::filesystem::path& folder,
                                                              std::string_view prefix, std::string_view suffix,
                                                              std::span<const std::string> written);

// P's pictures: "apcs001.png" … "apcs999.png" (number 1 … most_pictures); the first name not yet
// in the folder is written.
inline constexpr int most_pictures = 999;
std::string picture_file_name(int number);

} // namespace apcs
