#include "apcs/screens/replay_caption.h"

#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/painter.h"
#include "apcs/raster/screen_layout.h"

#include <algorithm>

namespace apcs {

namespace {

// Whether row `row` of `grid` shows nothing.
bool blank_row(const CellGrid& grid, int row)
{
    for (int column = 0; column < grid.columns(); ++column)
        if (grid.at(column, row) != U' ')
            return false;
    return true;
}

// `grid` moved up one row, its top row dropped and its bottom row blank.
CellGrid scrolled_up(const CellGrid& grid)
{
    CellGrid scrolled(grid.columns(), grid.rows());
    for (int row = 1; row < grid.rows(); ++row)
        for (int column = 0; column < grid.columns(); ++column) {
            scrolled.set(column, row - 1, grid.at(column, row));
            scrolled.set_style(column, row - 1, grid.style_at(column, row));
            for (const char32_t mark : grid.marks_at(column, row))
                scrolled.add_mark(column, row - 1, mark);
        }
    return scrolled;
}

// `text` after one blank column, padded with blanks to `columns`, so that a reverse bar spans the
// row (put_text clips what is wider; a script's captions are never wider: max_caption_columns).
std::string caption_bar(std::string_view text, int columns)
{
    // A caption fits 79 columns (the script's rule); "(skipped) " before one may push its end off
    // the row: it ends in "..." then, so the row says it is cut.
    std::string bar = " " + fitted_to_columns(text, columns - 1);
    // Padded by the columns the text takes, not its bytes: "สวัสดี" is 18 bytes in 4 columns.
    const int taken = text_columns(bar);
    if (taken < columns)
        bar.append(static_cast<std::size_t>(columns - taken), ' ');
    return bar;
}

// `label` cut to max_played_key_columns with " key " before it, "..." ending a cut.
std::string played_key_badge(std::string_view label)
{
    std::u32string characters = decode_utf8(label);
    constexpr std::size_t room = max_played_key_columns - 6;
    if (characters.size() > room)
        characters = characters.substr(0, room - 3) + U"...";
    std::string badge = " key ";
    for (const char32_t character : characters)
        append_utf8(badge, character);
    return badge + " ";
}

} // namespace

ProgramScreen with_caption(ProgramScreen screen, std::string_view caption)
{
    if (caption.empty())
        return screen;
    if (screen.graphics) {
        std::erase_if(screen.picture.text, [](const TextLine& line) { return line.row == layout::key_help_row; });
        // From column 0, so that the bar starts at the screen's edge like the console's.
        screen.picture.text.push_back(
            {0, layout::key_help_row, caption_bar(caption, text_screen_columns), CellStyle::reverse});
        return screen;
    }
    const int bottom = screen.text.rows() - 1;
    if (bottom < 0)
        return screen;
    if (!blank_row(screen.text, bottom))
        screen.text = scrolled_up(screen.text);
    screen.text.put_text(0, bottom, caption_bar(caption, screen.text.columns()), CellStyle::reverse);
    return screen;
}

CellGrid with_played_key(CellGrid grid, std::string_view label, std::string_view place)
{
    if ((label.empty() && place.empty()) || grid.rows() == 0)
        return grid;
    // Before any step (a lesson that opens on its first prompt) the place stands alone.
    const std::string after_label = place.empty() ? "" : "| " + std::string(place) + " ";
    const std::string badge = label.empty() ? " " + std::string(place) + " " : played_key_badge(label) + after_label;
    const int column = grid.columns() - 2 - text_columns(badge);
    if (column < 0)
        return grid;
    grid.put_text(column, 0, badge, CellStyle::reverse);
    return grid;
}

} // namespace apcs
