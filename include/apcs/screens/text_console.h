#pragma once

#include "apcs/raster/cell_grid.h"

#include <cstdint>
#include <string>
#include <vector>

namespace apcs {

// The DOS text screen of the session: 80x24, lines scroll up, the line being typed shows below
// the last printed line (input echoes on its own line).
class TextConsole {
public:
    static constexpr int columns = 80;
    static constexpr int rows = 24;

    // Prints text; '\n' ends a line; lines longer than 80 columns wrap.
    void print(const std::string& text);
    void print_line(const std::string& text) { print(text + "\n"); }
    void set_input(const std::string& input)
    {
        if (input != m_input)
            ++m_revision;
        m_input = input;
    }
    const std::string& input() const { return m_input; }
    // Moves the typed line into the history (after Enter).
    void commit_input();

    // The last 25 rows: history, then the input line with a cursor.
    CellGrid render(bool show_cursor = true) const;
    const std::vector<std::string>& lines() const { return m_lines; }
    // Advanced by every change of what render() shows: what is printed, typed or committed.
    std::uint64_t revision() const { return m_revision; }

private:
    std::vector<std::string> m_lines;
    std::string m_partial;
    std::string m_input;
    std::uint64_t m_revision = 0;
};

} // namespace apcs
