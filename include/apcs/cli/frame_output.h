#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/session/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/formats/diagnostic.h"

#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// "# frame 0" … "# frame K", each followed by its points (SPEC §7.4).
std::string format_frames_print(const FrameSequence& frames);

// Writes the in-betweens (every frame but the first and the last) as inb001.dat … into `folder`,
// each a whole graphic with the parts of `structure`. Files in `protected_files` (the key files)
// are never written. Returns the files written.
Expected<std::vector<std::filesystem::path>> write_inbetween_files(const FrameSequence& frames, const Graphic& structure,
                                                                   const std::filesystem::path& folder,
                                                                   std::span<const std::filesystem::path> protected_files);

// The end of a batch command: frames to `out` with --print, else the in-between files into --out
// (default: the current folder). Problems go to `err` as exit status 1.
ExitStatus deliver_frames(const FrameSequence& frames, const Graphic& structure, const CommonOptions& options,
                          std::span<const std::filesystem::path> key_files, std::ostream& out, std::ostream& err);

} // namespace apcs
