#include "apcs/formats/key_recording.h"

#include "apcs/base/utf8.h"
#include "apcs/formats/physical_key.h"

#include <algorithm>

namespace apcs {

namespace {

// A key the script can name by a token of its own: a physical key, or a printable character that
// does not start a comment.
bool has_token(const KeyEvent& key)
{
    if (key.key != Key::character)
        return find_physical_key(key.key) != nullptr;
    return is_token_character(key.character) && key.character != U';';
}

std::string token_line(const KeyEvent& key)
{
    if (key.key != Key::character)
        return std::string(find_physical_key(key.key)->script_name) + "\n";
    std::string line;
    append_utf8(line, key.character);
    return line + "\n";
}

// A character no token names (';', which starts a comment) as a TEXT line of its own.
std::string text_line(const KeyEvent& key)
{
    std::string line = "TEXT ";
    append_utf8(line, key.character);
    return line + "\n";
}

} // namespace

void KeyRecording::add_key(const KeyEvent& key, bool typed_text)
{
    m_entries.push_back({Entry::Kind::key, key, typed_text, {}});
}

std::string KeyRecording::text() const
{
    std::string script;
    for (const ScriptInput& input : m_inputs)
        script += input_line(input) + "\n";
    if (!m_options.empty())
        script += "OPTIONS " + m_options + "\n";
    std::string typed;
    for (const Entry& entry : m_entries) {
        const bool typing = entry.kind == Entry::Kind::key && entry.typed_text &&
                            (entry.key.key == Key::character || entry.key.key == Key::space) &&
                            entry.key.character != U';';
        if (typing) {
            append_utf8(typed, entry.key.key == Key::space ? U' ' : entry.key.character);
            continue;
        }
        script += take_text_line(typed);
        switch (entry.kind) {
        case Entry::Kind::key: script += has_token(entry.key) ? token_line(entry.key) : text_line(entry.key); break;
        case Entry::Kind::start: script += "START\n"; break;
        case Entry::Kind::caption: script += ";; " + entry.line + "\n"; break;
        case Entry::Kind::goal: script += entry.line + "\n"; break;
        }
    }
    return script + take_text_line(typed);
}

} // namespace apcs
