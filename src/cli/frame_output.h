#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/base/diagnostic.h"
#include "apcs/cli/options.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/formats/numbered_files.h"
#include "apcs/playback/animation_player.h"
#include "apcs/base/exit_status.h"

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// "# frame 0" … "# frame K", each followed by its points (SPEC §7.4).
std::string format_frames_print(const FrameSequence& frames);

// The frames `player` shows, from its first, `frame_count` of them, as an animated GIF to `target`
// (standard output for "-"), each shown `delay_ms`; an old GIF's backup never replaces one of
// `inputs`.
Expected<void> write_player_gif(AnimationPlayer& player, std::size_t frame_count,
                                const std::filesystem::path& target, int delay_ms,
                                const KeyFileGuard& inputs, std::ostream& out);

// The end of a batch command: all frames overlaid in the pictures --png and --png-raw name, the
// numbers to `out` with --print, and the in-between files into --out (write_inbetween_files) —
// into the current folder when neither a picture nor --print was asked —, never over one of
// `key_files` (KEY1, KEY2). Problems go to `err` as exit status 1.
ExitStatus deliver_frames(const FrameSequence& frames, const Graphic& structure, const CommonOptions& options,
                          std::span<const std::filesystem::path> key_files, std::ostream& out, std::ostream& err);

// Writes in-between files with `write` into --out (or the current folder), the key files and
// options.read_files guarded, its progress shown on a terminal's standard error (WriteProgressLine),
// and notes in-betweens an earlier run left beyond them: the files part of deliver_frames, also
// for frames streamed as they are made (apcs fit without pictures or --print).
using InbetweenWriter = std::function<Expected<std::vector<std::filesystem::path>>(
    const std::filesystem::path& folder, const KeyFileGuard& guard, const WriteProgress& progress)>;
ExitStatus deliver_inbetween_files(const InbetweenWriter& write, const CommonOptions& options,
                                   std::span<const std::filesystem::path> key_files, std::ostream& err);

} // namespace apcs
