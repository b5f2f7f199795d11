#include "apcs/session/replay_caption.h"

#include "apcs/session/screen_layout.h"

#include <algorithm>

namespace apcs {

SessionScreen with_caption(SessionScreen screen, std::string_view caption)
{
    if (caption.empty())
        return screen;
    if (screen.graphics) {
        std::erase_if(screen.picture.text, [](const TextLine& line) { return line.row == layout::message_row; });
        screen.picture.text.push_back({1, layout::message_row, std::string(caption), CellStyle::reverse});
        return screen;
    }
    const int bottom = screen.text.rows() - 1;
    // Padded to the width, so the reverse bar spans the row; put_text clips what is wider.
    std::string line(caption);
    const auto width = static_cast<std::size_t>(std::max(screen.text.columns(), 0));
    if (line.size() < width)
        line.append(width - line.size(), ' ');
    screen.text.put_text(0, bottom, line, CellStyle::reverse);
    return screen;
}

} // namespace apcs
