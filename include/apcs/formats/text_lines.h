#pragma once

#include "apcs/base/diagnostic.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace apcs {

inline constexpr std::size_t max_text_line_bytes = 4096;

// What a data line handler says: ok (go on) or the problem that ends the reading.
using DataLineHandler = std::function<Expected<void>(int line_number, std::string_view content)>;

// The lexical rules that .dat and .scn files share (SPEC §2.1): a UTF-8 byte-order mark is
// skipped; a Ctrl-Z may end the file (only line ends and blanks after it); lines end with LF,
// CR LF or a lone CR; a line holds at most max_text_line_bytes bytes and no NUL; ';' or '#'
// starts a comment that runs to the line's end. `handle` gets every line's content before its
// comment (blank lines too), numbered from 1; the first problem, its own or the handler's, ends
// the reading and is returned as "FILE:LINE: message" for `file_name`.
// The problem is the first in the file's order: a line before a misplaced Ctrl-Z is read first.
Expected<void> for_each_data_line(std::string_view text, const std::string& file_name, const DataLineHandler& handle);

// The same line ends and Ctrl-Z for a text whose lines are not data lines (a key script, whose
// TEXT lines keep ';' and '#'):
// the next line of `text`, taken off it (LF, CR LF or a lone CR ends it);
std::string_view take_line(std::string_view& text);
// `text` cut before a Ctrl-Z that ends it, or the problem "FILE:LINE: Ctrl-Z …" when more than
// line ends and blanks follow the Ctrl-Z.
Expected<void> cut_at_end_of_file(std::string_view& text, const std::string& file_name);

// FILE:LINE when `line` of a shared file (a key script, a scene) holds a character a terminal
// would obey (first_control_character): such text is refused at read, never echoed to a screen,
// a file name or a message (issue 45).
Expected<void> printable_line(std::string_view line, const std::string& file_name, int line_number);

// for_each_data_line for text that comes in pieces (a file read a block at a time): each line
// goes to the handler as soon as it is whole, so only an unfinished line is ever held. feed()
// and finish() return the first problem (and every later call returns it again).
class DataLineReader {
public:
    DataLineReader(const std::string& file_name, DataLineHandler handle);
    Expected<void> feed(std::string_view chunk);
    Expected<void> finish();

private:
    void decide_bom();
    // Handles the whole lines of `text` (all of it when at_end); returns how much it used.
    std::size_t take_lines(std::string_view text, bool at_end);
    void handle_line(std::string_view content);
    void check_trailer(std::string_view bytes);

    std::string m_file_name; // a copy: a caller may pass a temporary
    DataLineHandler m_handle;
    std::string m_pending; // the unfinished line
    bool m_bom_decided = false;
    bool m_ended = false; // a Ctrl-Z was read
    int m_end_line = 0;   // the line of the Ctrl-Z
    int m_line = 0;
    Expected<void> m_outcome = ok; // the first problem, once there is one
};

} // namespace apcs
