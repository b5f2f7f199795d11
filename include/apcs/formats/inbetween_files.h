#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/formats/diagnostic.h"
#include "apcs/formats/key_file_guard.h"

#include <filesystem>
#include <vector>

namespace apcs {

// Writes the in-betweens (every frame but the first and the last) as inb001.dat … into `folder`,
// each a whole graphic with the parts of `structure`, atomically and spread over the cores.
// Every target is checked against `guard` before any file is written: a guarded one (a key file)
// stops the whole writing. Returns the files written, or the first problem: a `folder` that is
// not a folder, a key file, or a file that could not be written.
[[nodiscard]] Expected<std::vector<std::filesystem::path>> write_inbetween_files(const FrameSequence& frames,
                                                                                 const Graphic& structure,
                                                                                 const std::filesystem::path& folder,
                                                                                 const KeyFileGuard& guard);

} // namespace apcs
