#include "apcs/formats/text_lines.h"

#include "apcs/formats/text_fields.h"

#include <algorithm>

namespace apcs {

namespace {

constexpr std::string_view utf8_byte_order_mark = "\xEF\xBB\xBF";
constexpr char dos_end_of_file = '\x1A';

// Removes the first line from `text` and returns it without its end. A line ends with LF (Unix),
// CR LF (DOS) or a lone CR (old Macintosh files), so each form numbers lines the same way.
std::string_view take_line(std::string_view& text)
{
    const std::size_t end = text.find_first_of("\r\n");
    const std::string_view line = text.substr(0, end);
    if (end == std::string_view::npos) {
        text = {};
        return line;
    }
    const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
    text.remove_prefix(end + (crlf ? 2 : 1));
    return line;
}

// The 1-based number of the line that holds byte `position` of `text`, with line ends as
// take_line finds them.
int line_number_at(std::string_view text, std::size_t position)
{
    int line = 1;
    for (std::size_t i = 0; i < position && i < text.size(); ++i) {
        const bool lone_cr = text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n');
        if (text[i] == '\n' || lone_cr)
            ++line;
    }
    return line;
}

} // namespace

std::optional<Diagnostic> for_each_data_line(std::string_view text, const std::string& file_name,
                                             const DataLineHandler& handle)
{
    if (text.starts_with(utf8_byte_order_mark))
        text.remove_prefix(utf8_byte_order_mark.size());
    // DOS editors ended a file with Ctrl-Z; anything but line ends after it is not a text file.
    const std::size_t end_mark = text.find(dos_end_of_file);
    if (end_mark != std::string_view::npos) {
        const std::string_view rest = text.substr(end_mark);
        const bool only_trailer = std::all_of(rest.begin(), rest.end(), [](char c) {
            return c == dos_end_of_file || c == '\r' || c == '\n' || is_field_blank(c);
        });
        if (!only_trailer)
            return Diagnostic{file_name, line_number_at(text, end_mark),
                              "Ctrl-Z (end of file) followed by more data; expected it only at the end"};
        text = text.substr(0, end_mark);
    }
    int line_number = 0;
    while (!text.empty()) {
        ++line_number;
        std::string_view content = take_line(text);
        if (content.size() > max_text_line_bytes)
            return Diagnostic{file_name, line_number,
                              "line is " + std::to_string(content.size()) + " bytes long; expected at most " +
                                  std::to_string(max_text_line_bytes)};
        if (content.find('\0') != std::string_view::npos)
            return Diagnostic{file_name, line_number, "NUL byte; expected a text file"};
        if (auto problem = handle(line_number, content.substr(0, content.find_first_of(";#"))))
            return problem;
    }
    return std::nullopt;
}

} // namespace apcs
