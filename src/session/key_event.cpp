#include "apcs/session/key_event.h"

#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/text_lines.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/painter.h"

#include <utility>

namespace apcs {

namespace {

// What a script line's token may be, for its error text: "a single printable character or ENTER,
// ESC, …" in the order of the physical keys.
std::string expected_token()
{
    std::string expected = "expected a single printable character or ";
    for (const PhysicalKey& row : physical_keys)
        expected += std::string(row.script_name) + (&row == &physical_keys.back() ? "" : ", ");
    return expected;
}

// The key a token names: a physical key's script name or a single printable character.
std::optional<KeyEvent> key_of_token(std::string_view token)
{
    for (const PhysicalKey& row : physical_keys)
        if (token == row.script_name)
            return KeyEvent::of(row.key);
    const std::u32string characters = decode_utf8(token);
    if (characters.size() != 1 || characters[0] < 0x21 || characters[0] == 0x7F || characters[0] == 0xFFFD)
        return std::nullopt;
    return KeyEvent::typed(characters[0]);
}

// The caption of a line's comment, if it starts with ";;": its text without the marks and the
// blanks around it.
std::optional<std::string> caption_of(std::string_view comment)
{
    if (!comment.starts_with(";;"))
        return std::nullopt;
    comment.remove_prefix(2);
    const std::size_t first = comment.find_first_not_of(" \t");
    if (first == std::string_view::npos)
        return std::string();
    const std::size_t last = comment.find_last_not_of(" \t");
    return std::string(comment.substr(first, last - first + 1));
}

Expected<std::vector<KeyEvent>> parse_script(std::string_view text, const std::string& file_name,
                                             std::vector<ScriptCaption>* captions)
{
    // Every event takes at least one byte of the script: one allocation, never a doubling.
    std::vector<KeyEvent> events;
    events.reserve(text.size());
    if (Expected<void> ended = cut_at_end_of_file(text, file_name); !ended)
        return ended.error();
    std::optional<Diagnostic> problem;
    int line_number = 0;
    while (!text.empty()) {
        ++line_number;
        std::string_view line = take_line(text);
        if (line.starts_with("TEXT ")) {
            for (const char32_t character : decode_utf8(line.substr(5)))
                events.push_back(character == U' ' ? KeyEvent::of(Key::space) : KeyEvent::typed(character));
            continue;
        }
        const std::size_t comment = line.find(';');
        const std::optional<std::string> caption =
            comment == std::string_view::npos ? std::nullopt : caption_of(line.substr(comment));
        line = line.substr(0, comment);
        for_each_field(line, [&](std::string_view token) {
            if (problem)
                return;
            if (const std::optional<KeyEvent> event = key_of_token(token))
                events.push_back(*event);
            else
                problem = Diagnostic{file_name, line_number, expected_token() + "; found " + quote_field(token)};
        });
        if (problem)
            return *problem;
        if (caption && captions != nullptr)
            captions->push_back({events.size(), *caption});
    }
    // Keys named by words (ENTER) take many bytes each: give back what they left unused.
    if (events.size() < events.capacity() / 2)
        events.shrink_to_fit();
    return events;
}

// The typed text `pending_text` as a script's TEXT line, emptying it. A TEXT line may not end in a
// space that an editor could strip, so its trailing spaces follow as SPACE tokens.
std::string take_text_line(std::string& pending_text)
{
    std::string trailing_spaces;
    while (pending_text.ends_with(' ')) {
        pending_text.pop_back();
        trailing_spaces += "SPACE\n";
    }
    std::string lines = pending_text.empty() ? std::string() : "TEXT " + pending_text + "\n";
    pending_text.clear();
    return lines + trailing_spaces;
}

} // namespace

Expected<std::vector<KeyEvent>> parse_key_script(std::string_view text, const std::string& file_name)
{
    return parse_script(text, file_name, nullptr);
}

Expected<KeyScript> parse_captioned_key_script(std::string_view text, const std::string& file_name)
{
    KeyScript script;
    Expected<std::vector<KeyEvent>> events = parse_script(text, file_name, &script.captions);
    if (!events)
        return events.error();
    script.events = std::move(*events);
    return script;
}

const ScriptCaption* caption_at(const KeyScript& script, std::size_t played)
{
    const ScriptCaption* shown = nullptr;
    for (const ScriptCaption& caption : script.captions)
        if (caption.before_event <= played)
            shown = &caption;
    return shown;
}

std::string format_key_script(const std::vector<KeyEvent>& events)
{
    std::string script;
    std::string pending_text;
    for (const KeyEvent& event : events) {
        // Text keeps its spaces inside a TEXT line.
        if (event.key == Key::character && event.character != U';') {
            append_utf8(pending_text, event.character);
            continue;
        }
        if (event.key == Key::space && !pending_text.empty()) {
            pending_text += ' ';
            continue;
        }
        script += take_text_line(pending_text);
        if (event.key == Key::character)
            script += "TEXT ;\n";
        else if (const PhysicalKey* row = find_physical_key(event.key))
            script += std::string(row->script_name) + "\n";
    }
    return script + take_text_line(pending_text);
}

} // namespace apcs
