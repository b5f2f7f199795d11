#pragma once

#include "apcs/base/utf8.h"

#include <map>
#include <string>
#include <string_view>
#include <optional>
#include <vector>

namespace apcs {

// How a cell is shown beyond its character: the terminal's attributes (SPEC §7.1: reverse video and
// bold are the terminal's only; pictures do not have them).
enum class CellStyle : unsigned char { plain, bold, reverse };

// What a cell is drawn in where the terminal has colour (SPEC §7.2.1), decided where each layer is
// painted; the terminal maps it to a colour of its own. `monitor` is the 1989 screen's one colour
// (curve, x marks, staff, text: the terminal's default foreground); each other role is an overlay
// that goes beyond the 1989 screen. Without colour every role is drawn alike.
enum class ColourRole : unsigned char { monitor, key_frame, ghost, inbetween, region, tangent, law, goal, reference };
inline constexpr ColourRole colour_roles[] = {ColourRole::monitor,   ColourRole::key_frame, ColourRole::ghost,
                                              ColourRole::reference, ColourRole::inbetween, ColourRole::region,
                                              ColourRole::tangent,   ColourRole::law,       ColourRole::goal};

// --color (SPEC §7.2.1): colour where the terminal has it (at least 8 colours), always, or never.
enum class ColourChoice : unsigned char { automatic, always, never };

// Which role a pixel or cell lit by two layers shows: an exercise's goal point > law inset > tangents > region > in-between
// marks > monitor (the curve, the 1989 marks) > pinned reference > ghost > key frames. The overlays a
// class turned on to see stand over the curve; the curve stands over what it is compared with (the
// reference, the ghost, the key frames).
int colour_priority(ColourRole role);
// One letter per role for test dumps: m k g i r t l o a.
char colour_letter(ColourRole role);
// The legend's name of the colour a terminal draws `role` in ("yellow"), and the colour number it
// means: 0-7 curses' black red green yellow blue magenta cyan white, 8-15 their bright kin (a
// terminal of 8 colours shows them as the colour 8 below, bold); monitor is the default
// foreground (-1).
std::string_view colour_name(ColourRole role);
int colour_number(ColourRole role);
// What the overlay of `role` is, for the legend ("tangents (T)").
std::string_view colour_role_name(ColourRole role);

// What a character terminal shows: columns x rows cells of one code point and one style each. A
// wide character fills two cells: its own, then one holding wide_tail. A cell may also hold the
// combining marks that follow its character (Thai vowel and tone marks, accents): zero-width
// characters a terminal puts in the same cell, as ncurses does (up to max_marks_per_cell).
class CellGrid {
public:
    // The right half of a wide character: painted by the character on its left, never by itself.
    static constexpr char32_t wide_tail = 0x110000;
    // ncurses keeps a base character and at most four marks in a cell (CCHARW_MAX 5); more would
    // show on no terminal, so they are left out here too.
    static constexpr std::size_t max_marks_per_cell = 4;

    CellGrid(int columns = 0, int rows = 0);

    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    char32_t at(int column, int row) const;
    CellStyle style_at(int column, int row) const;
    // The cell's character; its marks are cleared.
    void set(int column, int row, char32_t glyph);
    // The combining marks of the cell, in order; empty for most. A view, not a copy: the terminal
    // asks for every cell's at each repaint. Valid until the cell is next written.
    std::u32string_view marks_at(int column, int row) const;
    // Adds `mark` (a zero-width character) to the cell's marks, unless it holds max_marks_per_cell.
    void add_mark(int column, int row, char32_t mark);
    void set_style(int column, int row, CellStyle style);
    ColourRole role_at(int column, int row) const;
    void set_role(int column, int row, ColourRole role);
    // Writes UTF-8 text from (column, row) on, each character in cell_width columns, clipped at the
    // right edge (a wide character that would be cut in half is left out); a zero-width character
    // is a mark of the character before it (add_mark; left out when none is written before it),
    // control characters are left out, so the columns stay those of the terminal.
    void put_text(int column, int row, const std::string& utf8, CellStyle style = CellStyle::plain,
                  ColourRole role = ColourRole::monitor);
    bool operator==(const CellGrid&) const = default;

    // Row `row` as UTF-8, trailing spaces kept; a wide character appears once, each character
    // followed by its marks.
    std::string row_text(int row) const;
    // All rows, each followed by '\n'.
    std::string to_text() const;
    // The roles as letters (colour_letter), one row per line; a blank cell is a blank whatever its
    // role, so the dump reads beside to_text().
    std::string roles_text() const;

private:
    // Where cell (column, row) is in the row-major vectors; none outside the grid.
    std::optional<std::size_t> index_of(int column, int row) const;

    int m_columns;
    int m_rows;
    std::vector<char32_t> m_cells;
    std::vector<CellStyle> m_styles;
    std::vector<ColourRole> m_roles;
    // The marks of the few cells that have any, by their index in the vectors.
    std::map<std::size_t, std::u32string> m_marks;
};

} // namespace apcs
