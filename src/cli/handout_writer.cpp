#include "handout_writer.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/numbered_files.h"
#include "apcs/lesson/handout.h"
#include "apcs/lesson/handout_index.h"
#include "apcs/screens/replay_caption.h"

#include <algorithm>
#include <string>
#include <vector>

namespace apcs {

namespace {

constexpr std::string_view index_name = "index.html";

// An index.html that handout_index_html wrote: the mark of an earlier handout of APCS.
bool holds_handout_index(const std::filesystem::path& folder)
{
    constexpr std::uintmax_t largest_index = 16u << 20;
    const Expected<std::string> html = read_text_file(folder / index_name, largest_index);
    return html && is_handout_index(*html);
}

// The pages are written one by one as the replay reaches their captions: a page that is a link
// leading out of the folder is judged now, before the first page is written, not at its turn.
Expected<void> check_links_stay(const std::filesystem::path& folder, const std::vector<std::string>& names)
{
    for (const std::string& name : names)
        if (Expected<void> stays = check_link_stays_in_folder(folder / name); !stays)
            return stays;
    return ok;
}

// A handout's folder is APCS's: empty, or an earlier handout's (its index.html) holding only a
// handout's files, so that no file of the user's (their own index.html, index.bak, a page's .bak)
// is replaced.
Expected<void> check_handout_owned(const std::filesystem::path& folder, const std::vector<std::string>& names)
{
    if (names.empty())
        return ok;
    const std::string rule = "; a handout is written only into a new or empty folder, or over an earlier handout of APCS "
                             "(its index.html), so that no file of yours is replaced";
    if (!holds_handout_index(folder)) {
        const bool has_index = std::ranges::find(names, index_name) != names.end();
        return Diagnostic{folder.string(), 0,
                          has_index ? "holds an index.html that is not a handout's" + rule
                                    : "holds " + names.front() + ", and no handout's index.html" + rule};
    }
    for (const std::string& name : names)
        if (!is_handout_file_name(name))
            return Diagnostic{folder.string(), 0, "holds " + name + ", which is not a file of a handout" + rule};
    return ok;
}

std::vector<std::string> sorted_names_in(const std::filesystem::path& folder)
{
    std::vector<std::string> names = file_names_in(folder);
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

Expected<HandoutWriter> HandoutWriter::open(const std::filesystem::path& folder, PngInk ink)
{
    if (Expected<void> made = make_output_folder(folder, "the handout (--handout)"); !made)
        return made.error();
    // Opened first: the pages go into the folder checked here, however it is renamed or replaced
    // meanwhile.
    Expected<OutputFolder> opened = OutputFolder::open(folder);
    if (!opened)
        return opened.error();
    if (Expected<void> writable = check_writable(folder / index_name, ReadOnlyTarget::left_to_the_write); !writable)
        return writable.error();
    const std::vector<std::string> names = sorted_names_in(folder);
    if (Expected<void> stays = check_links_stay(folder, names); !stays)
        return stays.error();
    if (Expected<void> owned = check_handout_owned(folder, names); !owned)
        return owned.error();
    return HandoutWriter(std::move(*opened), ink);
}

std::vector<std::string> HandoutWriter::earlier_pages() const
{
    std::vector<std::string> earlier;
    for (const std::string& name : sorted_names_in(m_folder)) {
        const bool rewritten = std::ranges::any_of(m_written, [&name](const auto& file) { return file.filename() == name; });
        if (is_handout_page_name(name) && !rewritten)
            earlier.push_back((m_folder / name).string());
    }
    return earlier;
}

void HandoutWriter::write(int number, std::size_t count, PageCaption caption, const ProgramScreen& screen,
                          GlyphSet glyphs, const KeyFileGuard& inputs)
{
    if (!m_outcome || is_empty_prompt(screen))
        return;
    const ProgramScreen shown = with_caption(screen, caption.shown);
    const std::string stem = handout_file_stem(number, count, caption.written);
    const std::filesystem::path picture = m_folder / (stem + ".png");
    const Expected<std::string> png = encode_png(render_raster(screen_picture(shown)), PngShape::monitor, m_ink);
    if (!png) {
        m_outcome = Diagnostic{picture.string(), 0, "cannot encode the PNG image: " + png.error().to_string()};
        return;
    }
    m_last_backup.clear();
    write_file(stem + ".png", *png, inputs);
    write_file(stem + ".txt", screen_text(shown, glyphs), inputs);
    if (m_outcome)
        m_pages[number] = HandoutPage{number, stem + ".png", std::string(caption.shown)};
}

void HandoutWriter::finish(std::string_view title, const KeyFileGuard& inputs)
{
    std::vector<HandoutPage> pages;
    for (const auto& [number, page] : m_pages)
        pages.push_back(page);
    m_last_backup.clear();
    write_file(std::string(index_name), handout_index_html(title, pages), inputs);
}

void HandoutWriter::write_file(const std::string& name, std::string_view content, const KeyFileGuard& inputs)
{
    if (!m_outcome)
        return;
    KeyFileGuard kept = inputs;
    if (!m_last_backup.empty())
        kept.protect(m_last_backup);
    const Expected<WriteResult> written = write_file_atomically(m_output, name, content, &kept);
    if (!written) {
        m_outcome = written.error();
        return;
    }
    m_written.push_back(m_folder / name);
    m_last_backup = written->backup;
}

} // namespace apcs
