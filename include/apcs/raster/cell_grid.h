#pragma once

#include <string>
#include <vector>

namespace apcs {

// How a cell is shown beyond its character: the terminal's attributes (SPEC §7.1: reverse video and
// bold are the terminal's only; pictures do not have them).
enum class CellStyle : unsigned char { plain, bold, reverse };

// What a character terminal shows: columns x rows cells of one code point and one style each.
class CellGrid {
public:
    CellGrid(int columns = 0, int rows = 0);

    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    char32_t at(int column, int row) const;
    CellStyle style_at(int column, int row) const;
    void set(int column, int row, char32_t glyph);
    void set_style(int column, int row, CellStyle style);
    // Writes UTF-8 text from (column, row) on, clipped at the right edge.
    void put_text(int column, int row, const std::string& utf8, CellStyle style = CellStyle::plain);
    bool operator==(const CellGrid&) const = default;

    // Row `row` as UTF-8, trailing spaces kept.
    std::string row_text(int row) const;
    // All rows, each followed by '\n'.
    std::string to_text() const;

private:
    int m_columns;
    int m_rows;
    std::vector<char32_t> m_cells;
    std::vector<CellStyle> m_styles;
};

void append_utf8(std::string& text, char32_t code_point);

} // namespace apcs
