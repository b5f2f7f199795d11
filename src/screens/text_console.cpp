#include "apcs/screens/text_console.h"

#include "apcs/raster/painter.h"

#include <algorithm>

namespace apcs {

namespace {

// Splits a line into pieces of at most 80 columns, a wide character counting two (and never cut
// in half), so that each piece fills one row of the grid as the terminal shows it.
std::vector<std::string> wrap(const std::string& line)
{
    std::vector<std::string> pieces;
    std::string piece;
    int width = 0;
    for (const char32_t code_point : decode_utf8(line)) {
        const int columns = std::max(cell_width(code_point), 0);
        if (width + columns > TextConsole::columns) {
            pieces.push_back(piece);
            piece.clear();
            width = 0;
        }
        append_utf8(piece, code_point);
        width += columns;
    }
    pieces.push_back(piece);
    return pieces;
}

} // namespace

void TextConsole::print(const std::string& text)
{
    if (!text.empty())
        ++m_revision;
    for (const char c : text) {
        if (c == '\n') {
            for (std::string& piece : wrap(m_partial))
                m_lines.push_back(std::move(piece));
            m_partial.clear();
        } else {
            m_partial += c;
        }
    }
    // Only a bounded history is needed to draw 24 rows.
    constexpr std::size_t kept = 200;
    if (m_lines.size() > kept)
        m_lines.erase(m_lines.begin(), m_lines.end() - static_cast<std::ptrdiff_t>(kept));
}

void TextConsole::commit_input()
{
    print_line(m_input);
    m_input.clear();
}

CellGrid TextConsole::render(bool show_cursor) const
{
    std::vector<std::string> shown = m_lines;
    if (!m_partial.empty())
        shown.push_back(m_partial);
    std::vector<std::string> input_rows = wrap(m_input + (show_cursor ? "_" : ""));
    shown.insert(shown.end(), input_rows.begin(), input_rows.end());
    CellGrid grid(columns, rows);
    const std::size_t first = shown.size() > static_cast<std::size_t>(rows) ? shown.size() - static_cast<std::size_t>(rows) : 0;
    for (std::size_t i = first; i < shown.size(); ++i)
        grid.put_text(0, static_cast<int>(i - first), shown[i]);
    return grid;
}

} // namespace apcs
