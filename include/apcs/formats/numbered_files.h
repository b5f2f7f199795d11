#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/key_file_guard.h"

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// A run of files written into one folder (in-betweens inb001.dat …, scene frames frm000.dat …):
// file k (0 … count−1) is named name_of(k) and its content made by writer_of(k) chunk by chunk as
// it is written. Every target is checked against `guard` before any file is written (a guarded
// one stops the whole writing); each file is written atomically, the files spread over the cores,
// and one barrier (flush_file_system) puts them all on the disk before this returns, not one
// flush per file. Returns the files written, or the first problem: a `folder` that is not a
// folder ("expected an existing folder for PURPOSE"), a guarded file, or a file that could not be
// written.
[[nodiscard]] Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<void(std::size_t, const ContentSink&)>& writer_of, const KeyFileGuard& guard,
                     std::string_view purpose);

// The same with each file's whole text made by content_of(k) when it is written, so that one
// file's text per core is in memory at once.
[[nodiscard]] Expected<std::vector<std::filesystem::path>>
write_numbered_files(const std::filesystem::path& folder, std::size_t count,
                     const std::function<std::string(std::size_t)>& name_of,
                     const std::function<std::string(std::size_t)>& content_of, const KeyFileGuard& guard,
                     std::string_view purpose);

// P's pictures: "apcs001.png" … "apcs999.png" (number 1 … most_pictures); the first name not yet
// in the folder is written.
inline constexpr int most_pictures = 999;
std::string picture_file_name(int number);

} // namespace apcs
