#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/lesson/handout_index.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/screens/program_screen.h"

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// A page's caption: as the script writes it (the page's file name comes from it) and as the page
// shows it ("(not reached) …" before the caption closing a goal not reached).
struct PageCaption {
    std::string_view written;
    std::string_view shown;
};

// --handout DIR: per caption of a replay, DIR/NN-STEP.png (the screen as the monitor showed it,
// 720x522, as P and --png write pictures; black on white with --paper) and DIR/NN-STEP.txt (the
// 80x24 screen as text, as the headless replay prints it), names as handout.h gives them; at the
// end DIR/index.html, every page's picture and caption in order, for printing (handout_index.h).
class HandoutWriter {
public:
    // The writer of a handout into `folder`, its pictures in `ink`, made now when it is not there
    // (one level, as --out makes its folder: make_output_folder), so that a folder that cannot be
    // made, or an index.html there that cannot be replaced (a folder, a FIFO), stops the run before
    // the session starts. The folder must be new, empty or an earlier handout's (recognised by its
    // index.html, is_handout_index) holding only a handout's files (is_handout_file_name), and none
    // of its entries a link that leads out of it (check_link_stays_in_folder); else the first file
    // that is not is named and nothing is written.
    [[nodiscard]] static Expected<HandoutWriter> open(const std::filesystem::path& folder, PngInk ink = PngInk::monitor);

    // Caption number `number` (1, 2, …) of `count` at the end of its keys: `screen` is the
    // session's (the caption shown is laid on here), the text in `glyphs`. An empty prompt
    // (is_empty_prompt) gets no page. Each file is written atomically as every picture of APCS is:
    // an existing one is replaced (kept as NN-STEP.bak; identical content leaves it untouched),
    // never one of `inputs`. When the PNG's old content took NN-STEP.bak this time, the text's goes
    // to NN-STEP.b01 …, so that one backup never replaces the other. The first problem is kept
    // (outcome()); after it nothing more is written. A caption written again replaces its page.
    void write(int number, std::size_t count, PageCaption caption, const ProgramScreen& screen, GlyphSet glyphs,
               const KeyFileGuard& inputs);

    // DIR/index.html of the pages written, titled `title`, written as the pages are (never one of
    // `inputs`); nothing after a problem.
    void finish(std::string_view title, const KeyFileGuard& inputs);

    // ok, or the first write that failed.
    const Expected<void>& outcome() const { return m_outcome; }
    // The files written so far, in order.
    const std::vector<std::filesystem::path>& written() const { return m_written; }
    // The pages in the folder that this handout did not write (an earlier, longer lesson's), as
    // DIR/NAME in name order: named after the run, never deleted, as play --out names frames.
    std::vector<std::string> earlier_pages() const;

private:
    HandoutWriter(OutputFolder output, PngInk ink) : m_output(std::move(output)), m_folder(m_output.path()), m_ink(ink) {}
    void write_file(const std::string& name, std::string_view content, const KeyFileGuard& inputs);

    OutputFolder m_output;
    std::filesystem::path m_folder;
    PngInk m_ink;
    Expected<void> m_outcome = ok;
    std::vector<std::filesystem::path> m_written;
    std::map<int, HandoutPage> m_pages; // by caption number
    // The backup the last write_file kept, which the next file's backup must not replace.
    std::filesystem::path m_last_backup;
};

} // namespace apcs
