#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/session/session_settings.h"

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace apcs {

// --handout DIR: per caption of a replay, DIR/NN-STEP.png (the screen as the monitor showed it,
// 720x522, as P and --png write pictures) and DIR/NN-STEP.txt (the 80x24 screen as text, as the
// headless replay prints it), names as handout.h gives them.
class HandoutWriter {
public:
    // The writer of a handout into `folder`, made now when it is not there (one level, as --out
    // makes its folder: make_output_folder), so that a folder that cannot be made stops the run
    // before the session starts.
    [[nodiscard]] static Expected<HandoutWriter> open(const std::filesystem::path& folder);

    // Caption number `number` (1, 2, …) of `count` over `shown` (the caption already laid on it), the text in
    // `glyphs`. Each file is written atomically as every picture of APCS is: an existing one is
    // replaced (kept as NN-STEP.bak; identical content leaves it untouched), never one of `inputs`.
    // When the PNG's old content took NN-STEP.bak this time, the text's goes to NN-STEP.b01 …, so
    // that one backup never replaces the other. The first problem is kept (outcome()); after it
    // nothing more is written.
    void write(int number, std::size_t count, std::string_view caption, const SessionScreen& shown, GlyphSet glyphs,
               const KeyFileGuard& inputs);

    // ok, or the first write that failed.
    const Expected<void>& outcome() const { return m_outcome; }
    // The files written so far, in order.
    const std::vector<std::filesystem::path>& written() const { return m_written; }

private:
    explicit HandoutWriter(std::filesystem::path folder) : m_folder(std::move(folder)) {}

    std::filesystem::path m_folder;
    Expected<void> m_outcome = ok;
    std::vector<std::filesystem::path> m_written;
};

} // namespace apcs
