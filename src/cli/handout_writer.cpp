#include "apcs/cli/handout_writer.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/numbered_files.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/lesson/handout.h"

namespace apcs {

Expected<HandoutWriter> HandoutWriter::open(const std::filesystem::path& folder)
{
    if (Expected<void> made = make_output_folder(folder, "the handout (--handout)"); !made)
        return made.error();
    return HandoutWriter(folder);
}

void HandoutWriter::write(int number, std::size_t count, std::string_view caption, const SessionScreen& shown,
                          GlyphSet glyphs, const KeyFileGuard& inputs)
{
    if (!m_outcome)
        return;
    const std::filesystem::path stem = m_folder / handout_file_stem(number, count, caption);
    const std::optional<std::string> png = encode_png(render_raster(screen_picture(shown)), PngShape::monitor);
    if (!png) {
        m_outcome = Diagnostic{stem.string() + ".png", 0, "cannot encode the PNG image"};
        return;
    }
    const Expected<WriteResult> picture = write_file_atomically(stem.string() + ".png", *png, &inputs);
    if (!picture) {
        m_outcome = picture.error();
        return;
    }
    m_written.push_back(stem.string() + ".png");
    KeyFileGuard text_inputs = inputs;
    if (!picture->backup.empty())
        text_inputs.protect(picture->backup);
    const Expected<WriteResult> text = write_file_atomically(stem.string() + ".txt", screen_text(shown, glyphs), &text_inputs);
    if (!text) {
        m_outcome = text.error();
        return;
    }
    m_written.push_back(stem.string() + ".txt");
}

} // namespace apcs
