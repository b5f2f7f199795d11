#include "apcs/formats/text_lines.h"

#include "apcs/formats/text_fields.h"
#include "apcs/base/utf8.h"

#include <algorithm>

namespace apcs {

namespace {

constexpr std::string_view utf8_byte_order_mark = "\xEF\xBB\xBF";
constexpr char dos_end_of_file = '\x1A';

bool is_trailer(char c) { return c == dos_end_of_file || c == '\r' || c == '\n' || is_field_blank(c); }

// string_view::find_first_of looks each byte up in its set with a memchr of its own: for the
// lines of a 10^5-point key that was a fifth of apcs fit's time. One pass over the bytes instead.
template <typename Wanted>
std::size_t find_first(std::string_view text, std::size_t start, Wanted wanted)
{
    const auto found = std::find_if(text.begin() + static_cast<std::ptrdiff_t>(start), text.end(), wanted);
    return found == text.end() ? std::string_view::npos : static_cast<std::size_t>(found - text.begin());
}

// Where the line starting at `start` ends: a CR, an LF or DOS' end of file.
std::size_t line_end(std::string_view text, std::size_t start)
{
    return find_first(text, start, [](char c) { return c == '\n' || c == '\r' || c == dos_end_of_file; });
}

// Where a line's comment starts (';' or '#'), npos for none.
std::size_t comment_start(std::string_view line)
{
    return find_first(line, 0, [](char c) { return c == ';' || c == '#'; });
}

constexpr const char* more_after_end_of_file = "Ctrl-Z (end of file) followed by more data; expected it only at the end";

} // namespace

DataLineReader::DataLineReader(const std::string& file_name, DataLineHandler handle)
    : m_file_name(file_name)
    , m_handle(std::move(handle))
{
}

Expected<void> DataLineReader::feed(std::string_view chunk)
{
    if (!m_outcome || chunk.empty())
        return m_outcome;
    if (m_ended) {
        check_trailer(chunk);
        return m_outcome;
    }
    if (!m_bom_decided && m_pending.empty() && chunk.size() >= utf8_byte_order_mark.size()) {
        if (chunk.starts_with(utf8_byte_order_mark))
            chunk.remove_prefix(utf8_byte_order_mark.size());
        m_bom_decided = true;
    }
    if (m_pending.empty() && m_bom_decided) {
        // Whole lines straight from the chunk; only an unfinished last line is kept.
        const std::size_t used = take_lines(chunk, false);
        if (m_outcome && !m_ended)
            m_pending.assign(chunk.substr(used));
        return m_outcome;
    }
    m_pending.append(chunk);
    if (!m_bom_decided) {
        if (m_pending.size() < utf8_byte_order_mark.size())
            return ok;
        decide_bom();
    }
    const std::size_t used = take_lines(m_pending, false);
    m_pending.erase(0, used);
    return m_outcome;
}

Expected<void> DataLineReader::finish()
{
    if (!m_outcome || m_ended)
        return m_outcome;
    decide_bom();
    const std::size_t used = take_lines(m_pending, true);
    m_pending.erase(0, used);
    return m_outcome;
}

void DataLineReader::decide_bom()
{
    if (!m_bom_decided && std::string_view(m_pending).starts_with(utf8_byte_order_mark))
        m_pending.erase(0, utf8_byte_order_mark.size());
    m_bom_decided = true;
}

std::size_t DataLineReader::take_lines(std::string_view text, bool at_end)
{
    std::size_t start = 0;
    while (m_outcome) {
        const std::size_t end = line_end(text, start);
        if (end == std::string_view::npos) {
            if (!at_end || start == text.size())
                return start;
            handle_line(text.substr(start));
            return text.size();
        }
        if (text[end] == dos_end_of_file) {
            // DOS editors ended a file with Ctrl-Z: what stands before it on its line is the last
            // line; after it only line ends and blanks may follow.
            m_end_line = m_line + 1;
            if (end > start)
                handle_line(text.substr(start, end - start));
            m_ended = true;
            check_trailer(text.substr(end));
            return text.size();
        }
        // A CR at the end of what has come may be the first half of a CR LF.
        if (text[end] == '\r' && end + 1 == text.size() && !at_end)
            return start;
        const bool crlf = text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
        handle_line(text.substr(start, end - start));
        start = end + (crlf ? 2 : 1);
    }
    return start;
}

void DataLineReader::handle_line(std::string_view content)
{
    ++m_line;
    if (content.size() > max_text_line_bytes)
        m_outcome = Diagnostic{m_file_name, m_line,
                               "line is " + std::to_string(content.size()) + " bytes long; expected at most " +
                                   std::to_string(max_text_line_bytes)};
    else if (content.find('\0') != std::string_view::npos)
        m_outcome = Diagnostic{m_file_name, m_line, "NUL byte; expected a text file"};
    else
        m_outcome = m_handle(m_line, content.substr(0, comment_start(content)));
}

void DataLineReader::check_trailer(std::string_view bytes)
{
    if (m_outcome && !std::all_of(bytes.begin(), bytes.end(), is_trailer))
        m_outcome = Diagnostic{m_file_name, m_end_line, more_after_end_of_file};
}

Expected<void> for_each_data_line(std::string_view text, const std::string& file_name, const DataLineHandler& handle)
{
    DataLineReader reader(file_name, handle);
    if (Expected<void> fed = reader.feed(text); !fed)
        return fed;
    return reader.finish();
}

std::string_view take_line(std::string_view& text)
{
    const std::size_t end = text.find_first_of("\r\n");
    const std::string_view line = text.substr(0, end);
    const bool crlf =
        end != std::string_view::npos && text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n';
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + (crlf ? 2 : 1));
    return line;
}

Expected<void> cut_at_end_of_file(std::string_view& text, const std::string& file_name)
{
    const std::size_t end_of_file = text.find(dos_end_of_file);
    if (end_of_file == std::string_view::npos)
        return ok;
    const std::string_view after = text.substr(end_of_file + 1);
    if (!std::all_of(after.begin(), after.end(), is_trailer)) {
        int line = 1; // the Ctrl-Z's: one more than the line ends before it
        for (std::string_view before = text.substr(0, end_of_file);
             before.find_first_of("\r\n") != std::string_view::npos; ++line)
            take_line(before);
        return Diagnostic{file_name, line, more_after_end_of_file};
    }
    text = text.substr(0, end_of_file);
    return ok;
}

Expected<void> printable_line(std::string_view line, const std::string& file_name, int line_number)
{
    if (const std::optional<std::string> control = first_control_character(line))
        return Diagnostic{file_name, line_number,
                          "expected printable text; found the control character " + *control +
                              " (a terminal would obey it)"};
    return ok;
}

} // namespace apcs
