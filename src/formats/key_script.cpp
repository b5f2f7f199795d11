#include "apcs/formats/key_script.h"

#include "apcs/base/utf8.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"
#include "apcs/formats/text_lines.h"

#include <algorithm>
#include <limits>
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

// Whether `a` and `b` are the same word but for the case of ASCII letters.
bool same_word(std::string_view a, std::string_view b)
{
    const auto upper = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; };
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) {
               return upper(x) == upper(y);
           });
}

// The key a token names: a physical key's script name in any case (enter is ENTER: SPEC §3.2) or a
// single printable character, whose case is the character's.
std::optional<KeyEvent> key_of_token(std::string_view token)
{
    for (const PhysicalKey& row : physical_keys)
        if (token.size() > 1 ? same_word(token, row.script_name) : token == row.script_name)
            return KeyEvent::of(row.key);
    const std::u32string characters = decode_utf8(token);
    if (characters.size() != 1 || !is_token_character(characters[0]))
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

// The caption of a comment, checked against the caption row's width.
Expected<std::optional<std::string>> checked_caption(std::string_view comment, const std::string& file_name,
                                                     int line_number)
{
    std::optional<std::string> caption = caption_of(comment);
    if (caption && text_columns(*caption) > max_caption_columns)
        return Diagnostic{file_name, line_number,
                          "expected a caption of at most " + std::to_string(max_caption_columns) +
                              " columns (the key-hint row of the 80x24 screen); found " +
                              std::to_string(text_columns(*caption))};
    return caption;
}

// A TEXT line's keys: its characters, a space as the Space key.
void type_line(std::string_view typed, std::vector<KeyEvent>& events, std::vector<TypedLine>* typed_lines)
{
    const std::size_t first = events.size();
    for (const char32_t character : decode_utf8(typed))
        events.push_back(character == U' ' ? KeyEvent::of(Key::space) : KeyEvent::typed(character));
    if (typed_lines != nullptr && events.size() > first)
        typed_lines->push_back({first, events.size() - first});
}

// The goals whose answers are still open end before event `end`: a caption, a GOAL line or the
// script's end closes them.
// `open` is the first goal not yet closed; afterwards, none is open.
void end_answers(KeyScript& script, std::size_t& open, std::size_t end)
{
    for (; open < script.goals.size(); ++open)
        script.goals[open].answer_end = end;
}

// Where a script's START line stands: it ends the preamble, so it comes once, alone on its line,
// before the first caption and goal (they would be passed over inside the preamble's one step).
struct StartLine {
    int line_number = 0; // 0: none yet
    bool after_caption_or_goal = false;
};

// What parse_script keeps between lines besides the events.
struct ScriptState {
    StartLine start;
    std::size_t open_goal = 0; // the first goal whose answer has not ended
    int options_line = 0;      // the OPTIONS line's number; 0: none yet
};

// A line "START" (a comment may follow): its place checked, the preamble's end kept. Whether the
// line is one.
Expected<bool> take_start_line(std::string_view line, StartLine& start, std::size_t events, KeyScript* kept,
                               const std::string& file_name, int line_number)
{
    const std::string_view keys = line.substr(0, line.find(';'));
    bool named = false;
    bool alone = true;
    for_each_field(keys, [&](std::string_view token) {
        named = named || token == "START";
        alone = alone && token == "START";
    });
    if (!named)
        return false;
    const std::string expected = "; expected one START line, alone, before the first caption and GOAL (the keys "
                                 "before it play as one step)";
    if (!alone)
        return Diagnostic{file_name, line_number, "START shares its line with keys" + expected};
    if (start.line_number != 0)
        return Diagnostic{file_name, line_number,
                          "a second START (the first is on line " + std::to_string(start.line_number) + ")" + expected};
    if (start.after_caption_or_goal)
        return Diagnostic{file_name, line_number, "START after a caption or GOAL" + expected};
    start.line_number = line_number;
    if (kept != nullptr)
        kept->preamble_end = events;
    return true;
}

// An exercise's INPUT line (script_input.h): in the preamble, before START, the first caption and
// GOAL, since the inputs are checked before a replay begins; each file named once.
Expected<void> take_input_line(std::string_view line, const StartLine& start, KeyScript* kept,
                               const std::string& file_name, int line_number)
{
    Expected<ScriptInput> input = parse_input_line(line.substr(6), file_name, line_number);
    if (!input)
        return input.error();
    if (start.line_number != 0 || start.after_caption_or_goal)
        return Diagnostic{file_name, line_number,
                          "INPUT after START, a caption or GOAL; expected an exercise's INPUT lines in its preamble, "
                          "before START (they are checked before the replay begins)"};
    if (kept == nullptr)
        return ok;
    for (const ScriptInput& earlier : kept->inputs)
        if (equals_ignoring_case(earlier.name, input->name))
            return Diagnostic{file_name, line_number,
                              "a second INPUT " + input->name + " (the first is on line " +
                                  std::to_string(earlier.line_number) + "); expected each input named once"};
    kept->inputs.push_back(*input);
    return ok;
}

// "OPTIONS" alone or followed by a blank or a comment.
bool is_options_line(std::string_view line)
{
    constexpr std::string_view word = "OPTIONS";
    return line.starts_with(word) &&
           (line.size() == word.size() || std::string_view(" \t;").find(line[word.size()]) != std::string_view::npos);
}

// An OPTIONS line: before the first key, START, the first caption and GOAL, since the options are
// the session's before it begins; one at most, naming at least one option. Which options it may
// name is the command line's to say (script_options.h): here they are words.
Expected<void> take_options_line(std::string_view line, const StartLine& start, std::size_t events, KeyScript* kept,
                                 const std::string& file_name, int line_number, int& options_line)
{
    const std::string expected = "; expected one OPTIONS line before the script's first key, START, caption and "
                                 "GOAL, holding the session's options (OPTIONS --step 0.1)";
    if (options_line != 0)
        return Diagnostic{file_name, line_number,
                          "a second OPTIONS (the first is on line " + std::to_string(options_line) + ")" + expected};
    if (events > 0 || start.line_number != 0 || start.after_caption_or_goal)
        return Diagnostic{file_name, line_number, "OPTIONS after a key, START, a caption or GOAL" + expected};
    // Every option a script carries, each with a long value, takes some 300 bytes.
    constexpr std::size_t longest = 1024;
    if (line.size() > longest)
        return Diagnostic{file_name, line_number,
                          "OPTIONS line of " + std::to_string(line.size()) + " bytes; expected at most " +
                              std::to_string(longest) + ", each option once"};
    std::string words;
    for_each_field(line.substr(0, line.find(';')).substr(7), [&words](std::string_view word) {
        words += (words.empty() ? "" : " ") + std::string(word);
    });
    if (words.empty())
        return Diagnostic{file_name, line_number, "OPTIONS names no option" + expected};
    options_line = line_number;
    if (kept != nullptr)
        kept->options = {words, line_number};
    return ok;
}

// A GOAL line: its goal kept, the answers before it ended.
Expected<void> take_goal_line(std::string_view line, ScriptState& state, std::size_t events, KeyScript* kept,
                              const std::string& file_name, int line_number)
{
    state.start.after_caption_or_goal = true;
    Expected<ScriptGoal> goal = parse_goal_line(line.substr(5), file_name, line_number);
    if (!goal)
        return goal.error();
    if (kept != nullptr) {
        end_answers(*kept, state.open_goal, events);
        goal->before_event = goal->answer_end = events;
        goal->captions_before = kept->captions.size();
        kept->goals.push_back(*goal);
    }
    return ok;
}

// A START, INPUT, OPTIONS or GOAL line taken into `kept`. Whether the line is one of them.
Expected<bool> take_directive_line(std::string_view line, ScriptState& state, std::size_t events, KeyScript* kept,
                                   const std::string& file_name, int line_number)
{
    const Expected<bool> is_start = take_start_line(line, state.start, events, kept, file_name, line_number);
    if (!is_start || *is_start)
        return is_start;
    Expected<void> taken = ok;
    if (line.starts_with("INPUT "))
        taken = take_input_line(line, state.start, kept, file_name, line_number);
    else if (is_options_line(line))
        taken = take_options_line(line, state.start, events, kept, file_name, line_number, state.options_line);
    else if (line.starts_with("GOAL "))
        taken = take_goal_line(line, state, events, kept, file_name, line_number);
    else
        return false;
    if (!taken)
        return taken.error();
    return true;
}

// `line` with its first word in capitals and a tab after it a space, when that word is a keyword
// (START, INPUT, OPTIONS, GOAL, TEXT) in any case: the case of keywords does not count (SPEC §3.2).
// Any other line as it is.
std::string_view keyword_in_capitals(std::string_view line, std::string& respelled)
{
    const std::size_t end = std::min(line.find_first_of(" \t;"), line.size());
    const std::string_view first = line.substr(0, end);
    for (const std::string_view keyword : {"START", "INPUT", "OPTIONS", "GOAL", "TEXT"}) {
        if (!same_word(first, keyword) || (first == keyword && (end == line.size() || line[end] != '\t')))
            continue;
        respelled = std::string(keyword) + std::string(line.substr(end));
        if (end < line.size() && line[end] == '\t')
            respelled[end] = ' ';
        return respelled;
    }
    return line;
}

// A line of key tokens: its keys into `events`; its comment's caption, if the comment is one.
Expected<std::optional<std::string>> take_key_line(std::string_view line, std::vector<KeyEvent>& events,
                                                   const std::string& file_name, int line_number)
{
    const std::size_t comment = line.find(';');
    const Expected<std::optional<std::string>> caption =
        comment == std::string_view::npos ? Expected<std::optional<std::string>>(std::nullopt)
                                          : checked_caption(line.substr(comment), file_name, line_number);
    if (!caption)
        return caption.error();
    std::optional<Diagnostic> problem;
    for_each_field(line.substr(0, comment), [&](std::string_view token) {
        if (problem)
            return;
        if (const std::optional<KeyEvent> event = key_of_token(token))
            events.push_back(*event);
        else
            problem = Diagnostic{file_name, line_number, expected_token() + "; found " + quote_field(token)};
    });
    if (problem)
        return *problem;
    return *caption;
}

// The script's events; its captions, TEXT lines and goals into `kept` unless it is null.
Expected<std::vector<KeyEvent>> parse_script(std::string_view text, const std::string& file_name, KeyScript* kept,
                                             std::size_t most_keys = std::numeric_limits<std::size_t>::max())
{
    // Every event takes at least one byte of the script: one allocation, never a doubling.
    std::vector<KeyEvent> events;
    events.reserve(std::min(text.size(), most_keys));
    if (Expected<void> ended = cut_at_end_of_file(text, file_name); !ended)
        return ended.error();
    // A UTF-8 byte order mark, as Windows editors write one, is no key.
    constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";
    if (text.starts_with(byte_order_mark))
        text.remove_prefix(byte_order_mark.size());
    // Each event's line, kept with the captions.
    const auto note_lines = [kept, &events](int line) {
        if (kept != nullptr)
            kept->event_lines.resize(events.size(), line);
    };
    const auto too_many_keys = [&](int line) {
        return Diagnostic{file_name, line,
                          "too long: more than " + std::to_string(most_keys) + " keys, at most " +
                              std::to_string(most_keys) + " are read"};
    };
    int line_number = 0;
    ScriptState state;
    while (!text.empty()) {
        ++line_number;
        std::string respelled;
        std::string_view line = keyword_in_capitals(take_line(text), respelled);
        if (Expected<void> printable = printable_line(line, file_name, line_number); !printable)
            return printable.error();
        if (line.starts_with("TEXT ")) {
            type_line(line.substr(5), events, kept == nullptr ? nullptr : &kept->typed_lines);
            if (events.size() > most_keys)
                return too_many_keys(line_number);
            note_lines(line_number);
            continue;
        }
        const Expected<bool> directive = take_directive_line(line, state, events.size(), kept, file_name, line_number);
        if (!directive)
            return directive.error();
        if (*directive)
            continue;
        const Expected<std::optional<std::string>> caption = take_key_line(line, events, file_name, line_number);
        if (!caption)
            return caption.error();
        if (events.size() > most_keys)
            return too_many_keys(line_number);
        note_lines(line_number);
        state.start.after_caption_or_goal = state.start.after_caption_or_goal || caption->has_value();
        if (*caption && kept != nullptr) {
            end_answers(*kept, state.open_goal, events.size());
            kept->captions.push_back({events.size(), **caption});
            kept->caption_lines.push_back(line_number);
        }
    }
    if (kept != nullptr)
        end_answers(*kept, state.open_goal, events.size());
    // Keys named by words (ENTER) take many bytes each: give back what they left unused.
    if (events.size() < events.capacity() / 2)
        events.shrink_to_fit();
    return events;
}

// The TEXT line whose keys start at event `first`, if one does.
const TypedLine* typed_line_at(const KeyScript& script, std::size_t first)
{
    const auto typed = std::lower_bound(
        script.typed_lines.begin(), script.typed_lines.end(), first,
        [](const TypedLine& line, std::size_t event) { return line.first_event < event; });
    return typed != script.typed_lines.end() && typed->first_event == first ? &*typed : nullptr;
}

// An exercise (a script with GOAL lines) names its inputs' very bytes: apcs grade replays every
// recording on files of those bytes, and a goal met before any key must be impossible. Only a
// lesson may name an input by its presence alone.
Expected<void> exercise_inputs_have_checksums(const KeyScript& script, const std::string& file_name)
{
    if (script.goals.empty())
        return ok;
    for (const ScriptInput& input : script.inputs)
        if (!input.crc32)
            return Diagnostic{file_name, input.line_number,
                              "INPUT " + input.name + " without its CRC32 in an exercise (a script with GOAL "
                              "lines); expected INPUT NAME CRC32 XXXXXXXX, the file's checksum"};
    return ok;
}

} // namespace

Expected<std::vector<KeyEvent>> parse_key_script(std::string_view text, const std::string& file_name)
{
    return parse_script(text, file_name, nullptr);
}

Expected<KeyScript> parse_captioned_key_script(std::string_view text, const std::string& file_name,
                                               std::size_t most_keys)
{
    KeyScript script;
    Expected<std::vector<KeyEvent>> events = parse_script(text, file_name, &script, most_keys);
    if (!events)
        return events.error();
    script.events = std::move(*events);
    if (Expected<void> checked = exercise_inputs_have_checksums(script, file_name); !checked)
        return checked.error();
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

std::size_t step_length(const KeyScript& script, std::size_t first)
{
    if (first >= script.events.size())
        return 0;
    if (first < script.preamble_end)
        return script.preamble_end - first;
    const TypedLine* typed = typed_line_at(script, first);
    return typed == nullptr ? 1 : typed->event_count;
}

std::string step_label(const KeyScript& script, std::size_t first)
{
    if (first >= script.events.size())
        return {};
    if (first < script.preamble_end)
        return "START";
    if (const TypedLine* typed = typed_line_at(script, first)) {
        std::string label = "TEXT ";
        for (std::size_t event = first; event < first + typed->event_count; ++event)
            append_utf8(label, script.events[event].key == Key::space ? U' ' : script.events[event].character);
        return label;
    }
    const KeyEvent& event = script.events[first];
    if (event.key == Key::character) {
        std::string label;
        append_utf8(label, event.character);
        return label;
    }
    const PhysicalKey* row = find_physical_key(event.key);
    return row == nullptr ? std::string() : std::string(row->script_name);
}

bool is_token_character(char32_t character)
{
    return character > 0x20 && character != 0x7F && character != 0xFFFD;
}

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
