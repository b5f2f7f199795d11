#include "apcs/raster/cell_grid.h"

#include "apcs/raster/painter.h"

#include <algorithm>
#include <optional>

namespace apcs {

CellGrid::CellGrid(int columns, int rows)
    : m_columns(std::max(columns, 0))
    , m_rows(std::max(rows, 0))
    , m_cells(static_cast<std::size_t>(m_columns) * static_cast<std::size_t>(m_rows), U' ')
    , m_styles(m_cells.size(), CellStyle::plain)
    , m_roles(m_cells.size(), ColourRole::monitor)
{
}

std::optional<std::size_t> CellGrid::index_of(int column, int row) const
{
    if (column < 0 || row < 0 || column >= m_columns || row >= m_rows)
        return std::nullopt;
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(m_columns) + static_cast<std::size_t>(column);
}

char32_t CellGrid::at(int column, int row) const
{
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return U' ';
    return m_cells[*index];
}

CellStyle CellGrid::style_at(int column, int row) const
{
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return CellStyle::plain;
    return m_styles[*index];
}

void CellGrid::set_style(int column, int row, CellStyle style)
{
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return;
    m_styles[*index] = style;
}

ColourRole CellGrid::role_at(int column, int row) const
{
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return ColourRole::monitor;
    return m_roles[*index];
}

void CellGrid::set_role(int column, int row, ColourRole role)
{
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return;
    m_roles[*index] = role;
}

void CellGrid::set(int column, int row, char32_t glyph)
{
    const std::optional<std::size_t> found = index_of(column, row);
    if (!found)
        return;
    const std::size_t index = *found;
    // Half a wide character is never left behind: its other half becomes a blank.
    if (m_cells[index] == wide_tail && glyph != wide_tail) {
        m_cells[index - 1] = U' ';
        m_marks.erase(index - 1);
    }
    if (m_cells[index] != wide_tail && column + 1 < m_columns && m_cells[index + 1] == wide_tail)
        m_cells[index + 1] = U' ';
    m_cells[index] = glyph;
    m_marks.erase(index);
}

std::u32string_view CellGrid::marks_at(int column, int row) const
{
    if (m_marks.empty())
        return {};
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return {};
    const auto found = m_marks.find(*index);
    return found == m_marks.end() ? std::u32string_view() : std::u32string_view(found->second);
}

void CellGrid::add_mark(int column, int row, char32_t mark)
{
    const std::optional<std::size_t> index = index_of(column, row);
    if (!index)
        return;
    std::u32string& marks = m_marks[*index];
    if (marks.size() < max_marks_per_cell)
        marks += mark;
}

void CellGrid::put_text(int column, int row, const std::string& utf8, CellStyle style, ColourRole role)
{
    // The cell of the last character written, which a combining mark after it joins.
    std::optional<int> base;
    for (const char32_t code_point : decode_utf8(utf8)) {
        const int width = cell_width(code_point);
        if (width == 0 && base)
            add_mark(*base, row, code_point);
        if (width <= 0)
            continue;
        if (width == 2 && column + 1 >= m_columns)
            break;
        base = column < m_columns ? std::optional<int>(column) : std::nullopt;
        set_style(column, row, style);
        set_role(column, row, role);
        set(column++, row, code_point);
        if (width == 2) {
            set_style(column, row, style);
            set_role(column, row, role);
            set(column++, row, wide_tail);
        }
    }
}

std::string CellGrid::row_text(int row) const
{
    std::string text;
    for (int column = 0; column < m_columns; ++column) {
        if (at(column, row) == wide_tail)
            continue;
        append_utf8(text, at(column, row));
        for (const char32_t mark : marks_at(column, row))
            append_utf8(text, mark);
    }
    return text;
}

std::string CellGrid::to_text() const
{
    std::string text;
    for (int row = 0; row < m_rows; ++row)
        text += row_text(row) + '\n';
    return text;
}

std::string CellGrid::roles_text() const
{
    std::string text;
    for (int row = 0; row < m_rows; ++row) {
        for (int column = 0; column < m_columns; ++column) {
            const char32_t glyph = at(column, row);
            text += glyph == U' ' || glyph == U'\u2800' ? ' ' : colour_letter(role_at(column, row));
        }
        text += '\n';
    }
    return text;
}

namespace {

struct RoleColour {
    ColourRole role;
    int priority;
    char letter;
    std::string_view colour;
    int number; // 0-7 curses' COLOR_* (black red green yellow blue magenta cyan white), 8-15 bright
    std::string_view name;
};

// The one table of the roles' colours (SPEC §7.2.1, §3.2): each at least 4.5:1 against black in
// xterm's default palette, so that a projector's back row sees it. Blue (2.2:1), red (3.6:1) and
// magenta (4.48:1) fail there, and so does bright blue (4.4:1): the ghost is grey (bright black,
// 5.2:1), the marks bright red (5.3:1), the region bright magenta (6.7:1), named as a person
// sees them: red, magenta.
constexpr RoleColour role_colours[] = {
    {ColourRole::monitor, 3, 'm', "the terminal's own", -1, "curve, x marks, staff, text (1989)"},
    {ColourRole::key_frame, 0, 'k', "cyan", 6, "key frames (K)"},
    {ColourRole::ghost, 1, 'g', "grey", 8, "ghost (O)"},
    // Green as the law's: the law is an inset graph in a corner, never a curve beside the path.
    {ColourRole::reference, 2, 'a', "green", 2, "reference A, pinned (C)"},
    {ColourRole::inbetween, 4, 'i', "red", 9, "in-between marks"},
    {ColourRole::region, 5, 'r', "magenta", 13, "picked region"},
    {ColourRole::tangent, 6, 't', "yellow", 3, "tangents (T)"},
    {ColourRole::law, 7, 'l', "green", 2, "law (G)"},
    {ColourRole::goal, 8, 'o', "reverse", -1, "goal"},
};

const RoleColour& colour_of(ColourRole role)
{
    for (const RoleColour& entry : role_colours)
        if (entry.role == role)
            return entry;
    return role_colours[0];
}

} // namespace

int colour_priority(ColourRole role) { return colour_of(role).priority; }
char colour_letter(ColourRole role) { return colour_of(role).letter; }
std::string_view colour_name(ColourRole role) { return colour_of(role).colour; }
int colour_number(ColourRole role) { return colour_of(role).number; }
std::string_view colour_role_name(ColourRole role) { return colour_of(role).name; }

} // namespace apcs
