#pragma once

// A terminal for the one terminal loop (run_program_on) without a terminal: what it reads comes
// from a queue, what it shows is kept, its clock moves only as the test says.
#include "apcs/terminal/terminal_device.h"

#include <chrono>
#include <deque>
#include <string>
#include <vector>

namespace apcs::test {

class FakeTerminal final : public TerminalDevice {
public:
    // What read_key answers next: a key, a time-out, a resize to `size`, or stop.
    struct Input {
        TerminalInput kind = TerminalInput::key;
        KeyEvent key = {};
        TerminalSize size = {};
    };
    static Input key(KeyEvent event) { return {TerminalInput::key, event, {}}; }
    static Input typed(char32_t character) { return key(KeyEvent::typed(character)); }
    static Input resize(TerminalSize size) { return {TerminalInput::resize, {}, size}; }

    std::deque<Input> inputs;
    // A key read moves the clock on by this much (a key typed every `per_read`); a time-out by the
    // wait asked; each look at the clock (now()) by `per_look`, the time work takes between them.
    std::chrono::milliseconds per_read{0};
    std::chrono::milliseconds per_look{0};
    // What show() was given, in order, and whether it sent every cell.
    std::vector<CellGrid> shown;
    std::vector<bool> shown_whole;
    // The time-out of each read_key, in order.
    std::vector<int> waits;
    int redraws = 0;

    TerminalSize size() const override { return m_size; }

    // The queue's next input; once it is empty, a time-out to a loop that only looks (timeout_ms
    // 0 or more) and stop to one that would wait for ever: the test's end.
    TerminalInput read_key(int timeout_ms, KeyEvent& key) override
    {
        waits.push_back(timeout_ms);
        if (inputs.empty()) {
            if (timeout_ms < 0)
                return TerminalInput::stop;
            m_clock += std::chrono::milliseconds(timeout_ms);
            return TerminalInput::timeout;
        }
        m_clock += per_read;
        const Input input = inputs.front();
        inputs.pop_front();
        key = input.key;
        if (input.kind == TerminalInput::resize)
            m_size = input.size;
        return input.kind;
    }

    bool show(const CellGrid& grid) override
    {
        const bool whole = m_whole_next || grid.columns() != m_shown_size.columns || grid.rows() != m_shown_size.rows;
        m_whole_next = false;
        m_shown_size = {grid.columns(), grid.rows()};
        shown.push_back(grid);
        shown_whole.push_back(whole);
        return whole;
    }
    void invalidate() override { m_whole_next = true; }
    void redraw() override
    {
        ++redraws;
        m_whole_next = true;
    }

    std::optional<CellPixels> cell_pixels() const override { return std::nullopt; }
    std::optional<PictureLimit> sixel_limit() const override { return std::nullopt; }
    void send_picture(int, int, std::string_view) override {}
    void remove_pictures(TerminalPictureProtocol) override {}

    std::chrono::steady_clock::time_point now() const override
    {
        m_clock += per_look;
        return m_clock;
    }

    // The text of a grid's row, blanks at its end cut.
    static std::string row_of(const CellGrid& grid, int row)
    {
        std::string text = grid.row_text(row);
        text.erase(text.find_last_not_of(' ') + 1);
        return text;
    }

private:
    TerminalSize m_size{80, 24};
    TerminalSize m_shown_size{};
    bool m_whole_next = true;
    mutable std::chrono::steady_clock::time_point m_clock{};
};

} // namespace apcs::test
