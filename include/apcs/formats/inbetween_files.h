#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/surface_fit.h"
#include "apcs/base/diagnostic.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/formats/numbered_files.h"

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// Writes the in-betweens (every frame but the first and the last) as inb001.dat … into `folder`,
// each a whole graphic with the parts of `structure`, atomically and spread over the cores.
// Every target is checked against `guard` before any file is written: a guarded one (a key file)
// stops the whole writing; `progress` is told of each file written. Returns the files written, or
// the first problem: a `folder` that is not a folder, a key file, or a file that could not be
// written.
[[nodiscard]] Expected<std::vector<std::filesystem::path>> write_inbetween_files(const FrameSequence& frames,
                                                                                 const Graphic& structure,
                                                                                 const std::filesystem::path& folder,
                                                                                 const KeyFileGuard& guard,
                                                                                 const WriteProgress& progress = {});

// write_inbetween_files for frames made as they are written: each in-between of `fitter` (frames
// 1 … frame_count − 2) is computed, formatted and written a chunk of points at a time, one file
// per core, so that no frame is ever whole in memory (SPEC's streaming of issue 18: the keys and
// a few chunks are all that is held).
[[nodiscard]] Expected<std::vector<std::filesystem::path>> write_inbetween_files(const SurfaceFitter& fitter,
                                                                                 const Graphic& structure,
                                                                                 const std::filesystem::path& folder,
                                                                                 const KeyFileGuard& guard,
                                                                                 const WriteProgress& progress = {});

// Of `names` (a folder's file names), the in-between files numbered above `written_count`
// (inb013.dat … when 12 were written now; any case, as DOS wrote them), in number order: what an
// earlier run with more in-betweens left behind. They are never deleted, only pointed out.
[[nodiscard]] std::vector<std::string> inbetweens_beyond(std::span<const std::string> names, std::size_t written_count);

// inbetweens_beyond for the files of `folder`.
[[nodiscard]] std::vector<std::string> inbetweens_beyond(const std::filesystem::path& folder, std::size_t written_count);

// "inb013.dat to inb020.dat (8 files) are from an earlier run (not rewritten)" for `earlier`
// (from inbetweens_beyond, or a play --out's frames from earlier_numbered_files), "inb013.dat is
// from ..." for one; nullopt for none.
[[nodiscard]] std::optional<std::string> earlier_inbetweens_note(std::span<const std::string> earlier);

} // namespace apcs
