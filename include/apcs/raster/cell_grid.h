#pragma once

#include <string>
#include <vector>

namespace apcs {

// How a cell is shown beyond its character: the terminal's attributes (SPEC §7.1: reverse video and
// bold are the terminal's only; pictures do not have them).
enum class CellStyle : unsigned char { plain, bold, reverse };

// How many terminal columns `code_point` takes: 1, 2 for East Asian wide ones (CJK, fullwidth
// forms, most emoji), 0 for combining and other zero-width ones, -1 for control characters. The
// same on every machine: Unicode's widths as the C.UTF-8 locale knows them, whatever the user's
// locale (a wide character counts 1 only where that locale is missing).
int cell_width(char32_t code_point);

// What a character terminal shows: columns x rows cells of one code point and one style each. A
// wide character fills two cells: its own, then one holding wide_tail.
class CellGrid {
public:
    // The right half of a wide character: painted by the character on its left, never by itself.
    static constexpr char32_t wide_tail = 0x110000;

    CellGrid(int columns = 0, int rows = 0);

    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    char32_t at(int column, int row) const;
    CellStyle style_at(int column, int row) const;
    void set(int column, int row, char32_t glyph);
    void set_style(int column, int row, CellStyle style);
    // Writes UTF-8 text from (column, row) on, each character in cell_width columns, clipped at the
    // right edge (a wide character that would be cut in half is left out); zero-width and control
    // characters are left out, so the columns stay those of the terminal.
    void put_text(int column, int row, const std::string& utf8, CellStyle style = CellStyle::plain);
    bool operator==(const CellGrid&) const = default;

    // Row `row` as UTF-8, trailing spaces kept; a wide character appears once.
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
