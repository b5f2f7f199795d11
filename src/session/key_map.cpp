#include "apcs/session/key_map.h"

#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"

#include <algorithm>
#include <array>
#include <vector>

namespace apcs {

namespace {

using Pattern = KeyPattern;
using Context = KeyContext;
namespace cmd = command;

// A row without its context: the table below gives each context its rows.
struct Row {
    Pattern pattern;
    Command command;
    std::string_view help;
    std::string_view meaning;
};

// The keys every step of graphics mode shares (SPEC §3, §7.3).
constexpr std::array graphics_rows{
    Row{Pattern::exactly(U'?'), cmd::ShowHelp{}, "? help", "this help"},
    Row{Pattern::of(Key::f1), cmd::ShowHelp{}, "", "this help"},
    Row{Pattern::letter(U'P'), cmd::SavePicture{}, "", "write the screen as apcsNNN.png in the work folder"},
};

std::vector<KeyBinding> make_bindings()
{
    std::vector<KeyBinding> table;
    const auto add = [&](Context context, const std::vector<Row>& rows) {
        for (const Row& row : rows)
            table.push_back({context, row.pattern, row.command, row.help, row.meaning});
    };
    // A full key line leaves "q quit" to the help screen.
    const auto add_graphics_rows = [&](Context context, std::string_view quit_meaning, bool quit_on_key_line = true) {
        add(context, std::vector<Row>(graphics_rows.begin(), graphics_rows.end()));
        add(context, {Row{Pattern::letter(U'Q'), cmd::Quit{}, quit_on_key_line ? "q quit" : "", quit_meaning}});
    };
    const Row help_key{Pattern::of(Key::f1), cmd::ShowHelp{}, "", "this help"};
    const Row question_mark{Pattern::exactly(U'?'), cmd::ShowHelp{}, "", "this help"};
    const Row quit_now{Pattern::letter(U'Q'), cmd::Quit{}, "", "end APCS; every file written so far stays"};
    const Row key_frames{Pattern::letter(U'K'), cmd::ToggleKeyFrames{}, "K/T/G show",
                         "show or hide both key frames, dotted, beside the path"};
    const Row tangents{Pattern::letter(U'T'), cmd::ToggleTangents{}, "K/T/G show",
                       "tangents on/off: DD leaving (solid), DS arriving (dashed)"};
    const Row law_graph{Pattern::letter(U'G'), cmd::ToggleLawGraph{}, "K/T/G show",
                        "law graph on/off: distance against frame in the span"};
    // The same key without words on the key line, where the line is full.
    const auto unlabelled = [](Row row) {
        row.help = "";
        return row;
    };
    const Row undo{Pattern::letter(U'U'), cmd::Undo{}, "U undo", "undo the last change of this path"};
    const Row tangent_next{Pattern::of(Key::tab), cmd::ChoosePoint{+1}, "",
                           "the tangents' numbers of the next control point"};
    const Row tangent_previous{Pattern::of(Key::back_tab), cmd::ChoosePoint{-1}, "",
                               "the tangents' numbers of the previous control point"};
    constexpr std::string_view quit_path = "end APCS without saving this path (asks first)";

    // Text prompts: every printable key is typed; Esc clears the line (SPEC §7.3).
    add(Context::text_line,
        {Row{Pattern::of(Key::enter), cmd::SubmitLine{}, "", "answer (an empty line takes the value in brackets)"},
         Row{Pattern::of(Key::backspace), cmd::EraseCharacter{}, "", "erase the last character"},
         Row{Pattern::of(Key::escape), cmd::ClearLine{}, "", "clear the line"},
         Row{Pattern::of(Key::f1), cmd::ShowHelp{}, "", "this help (so does the answer ? alone)"},
         Row{Pattern::of(Key::space), cmd::TypeCharacter{U' '}, "", ""},
         Row{Pattern::printable(), cmd::TypeCharacter{}, "", "typed into the answer"}});
    add(Context::yes_to_go_on,
        {Row{Pattern::letter(U'Y'), cmd::Yes{}, "", "adjust the next path"}, help_key, question_mark, quit_now});
    add(Context::enter_to_go_on,
        {Row{Pattern::of(Key::enter), cmd::Continue{}, "", "stop adjusting: surface fitting writes the in-betweens"},
         help_key, question_mark, quit_now});
    add(Context::any_key, {help_key, question_mark, quit_now, Row{Pattern::any_key(), cmd::Continue{}, "", "go on"}});
    add(Context::splitting,
        {Row{Pattern::of(Key::escape), cmd::Back{}, "", "stop the split: back to the KEY2 prompt (files written stay)"},
         quit_now});
    add(Context::any_key_graphics, std::vector<Row>(graphics_rows.begin(), graphics_rows.end()));
    add(Context::any_key_graphics, {quit_now, Row{Pattern::any_key(), cmd::Continue{}, "", "go on"}});

    // Check_GorL_Control: the keypad's 8 and 2, or the arrows on them.
    add(Context::control_choice,
        {Row{Pattern::exactly(U'8'), cmd::ChooseGlobal{}, "", "global control: the staff adjusts the whole path"},
         Row{Pattern::of(Key::up), cmd::ChooseGlobal{}, "", "global control: the staff adjusts the whole path"},
         Row{Pattern::exactly(U'2'), cmd::ChooseLocal{}, "", "local control: pick a region of control points"},
         Row{Pattern::of(Key::down), cmd::ChooseLocal{}, "", "local control: pick a region of control points"},
         Row{Pattern::letter(U'W'), cmd::OpenWaypoints{}, "W waypoints",
             "the waypoint editor: insert, delete and move control points"},
         undo, key_frames, tangents, law_graph});
    add_graphics_rows(Context::control_choice, quit_path);

    // Scan_Control_Point: the message line says what 4/6 and Enter do.
    add(Context::region_pick,
        {Row{Pattern::exactly(U'4'), cmd::ArrowMove{-1}, "", "the arrow to the previous control point"},
         Row{Pattern::of(Key::left), cmd::ArrowMove{-1}, "", "the arrow to the previous control point"},
         Row{Pattern::exactly(U'6'), cmd::ArrowMove{+1}, "", "the arrow to the next control point"},
         Row{Pattern::of(Key::right), cmd::ArrowMove{+1}, "", "the arrow to the next control point"},
         Row{Pattern::of(Key::enter), cmd::Accept{}, "", "pick the control point the arrow points at"},
         Row{Pattern::of(Key::escape), cmd::Back{}, "", "one step back"}, key_frames, tangents, law_graph});
    add_graphics_rows(Context::region_pick, quit_path);

    // Scan_Parameters / tnextpixel (thesis fig. 3.1.5).
    add(Context::staff,
        {Row{Pattern::exactly(U'4'), cmd::StaffStep{-1}, "4/6 J/L step", "the value one step left"},
         Row{Pattern::of(Key::left), cmd::StaffStep{-1}, "", "the value one step left"},
         Row{Pattern::exactly(U'6'), cmd::StaffStep{+1}, "", "the value one step right"},
         Row{Pattern::of(Key::right), cmd::StaffStep{+1}, "", "the value one step right"},
         Row{Pattern::letter(U'J'), cmd::StaffStep{-3}, "", "three steps left (Shift-J)"},
         Row{Pattern::letter(U'L'), cmd::StaffStep{+3}, "", "three steps right (Shift-L)"},
         Row{Pattern::exactly(U'='), cmd::OpenValueField{}, "= type", "type the value on the message line"},
         Row{Pattern::of(Key::enter), cmd::Accept{}, "Enter accept", "accept the value, go to the next line"},
         Row{Pattern::of(Key::escape), cmd::Keep{}, "Esc keep", "leave the line as it was, go to the next"},
         undo, key_frames, tangents, law_graph, tangent_next, tangent_previous});
    add_graphics_rows(Context::staff, quit_path, false);

    // "=": the value typed on the message line, as at a text prompt.
    add(Context::value_field,
        {Row{Pattern::of(Key::enter), cmd::SubmitLine{}, "Enter set", "set the line to the typed value"},
         Row{Pattern::of(Key::backspace), cmd::EraseCharacter{}, "Backspace erase", "erase the last character"},
         Row{Pattern::of(Key::escape), cmd::ClearLine{}, "Esc close", "close the field; the value stays"},
         Row{Pattern::of(Key::f1), cmd::ShowHelp{}, "", "this help"},
         Row{Pattern::of(Key::space), cmd::TypeCharacter{U' '}, "", ""},
         Row{Pattern::printable(), cmd::TypeCharacter{}, "", "typed into the value"}});

    // The waypoint editor: the keypad moves the chosen control point in the screen's plane.
    const Row choose_next{Pattern::of(Key::tab), cmd::ChoosePoint{+1}, "Tab point", "choose the next control point"};
    const Row choose_previous{Pattern::of(Key::back_tab), cmd::ChoosePoint{-1}, "",
                              "choose the previous control point"};
    add(Context::waypoints,
        {choose_next, choose_previous,
         Row{Pattern::exactly(U']'), cmd::ChoosePoint{+1}, "", "choose the next control point"},
         Row{Pattern::exactly(U'['), cmd::ChoosePoint{-1}, "", "choose the previous control point"},
         Row{Pattern::exactly(U'4'), cmd::MovePoint{-1, 0, 0}, "2468 +- move", "move the point one step left, right"},
         Row{Pattern::of(Key::left), cmd::MovePoint{-1, 0, 0}, "", "move the point one step left, right"},
         Row{Pattern::exactly(U'6'), cmd::MovePoint{+1, 0, 0}, "", "move the point one step left, right"},
         Row{Pattern::of(Key::right), cmd::MovePoint{+1, 0, 0}, "", "move the point one step left, right"},
         Row{Pattern::exactly(U'8'), cmd::MovePoint{0, +1, 0}, "", "move the point one step up, down the screen"},
         Row{Pattern::of(Key::up), cmd::MovePoint{0, +1, 0}, "", "move the point one step up, down the screen"},
         Row{Pattern::exactly(U'2'), cmd::MovePoint{0, -1, 0}, "", "move the point one step up, down the screen"},
         Row{Pattern::of(Key::down), cmd::MovePoint{0, -1, 0}, "", "move the point one step up, down the screen"},
         Row{Pattern::letter(U'J'), cmd::MovePoint{-3, 0, 0}, "", "three steps left, right (Shift-J, Shift-L)"},
         Row{Pattern::letter(U'L'), cmd::MovePoint{+3, 0, 0}, "", "three steps left, right (Shift-J, Shift-L)"},
         Row{Pattern::exactly(U'+'), cmd::MovePoint{0, 0, +1}, "", "one step toward, away from the viewer"},
         Row{Pattern::exactly(U'-'), cmd::MovePoint{0, 0, -1}, "", "one step toward, away from the viewer"},
         Row{Pattern::letter(U'I'), cmd::InsertPoint{}, "I/D ins/del", "insert a control point after the chosen one"},
         Row{Pattern::letter(U'D'), cmd::DeletePoint{}, "", "delete the chosen control point"},
         Row{Pattern::letter(U'U'), cmd::Undo{}, "U undo", "undo the last change in the editor"},
         Row{Pattern::of(Key::enter), cmd::Accept{}, "Enter keep", "leave the editor keeping the changes"},
         Row{Pattern::of(Key::escape), cmd::Back{}, "Esc drop", "leave the editor undoing its changes"},
         unlabelled(key_frames), unlabelled(tangents), unlabelled(law_graph)});
    add_graphics_rows(Context::waypoints, quit_path, false);

    // Ask_Adjusting: Y again; N or Enter accepts the path; other keys are not an answer.
    add(Context::adjust_again,
        {Row{Pattern::letter(U'Y'), cmd::Yes{}, "", "adjust the path again"},
         Row{Pattern::letter(U'N'), cmd::No{}, "", "accept the path: it is written back with its values"},
         Row{Pattern::of(Key::enter), cmd::No{}, "", "accept the path: it is written back with its values"},
         undo, key_frames, tangents, law_graph});
    add_graphics_rows(Context::adjust_again, quit_path);

    // Showing_Animation.
    add(Context::animation,
        {Row{Pattern::of(Key::escape), cmd::StopAnimation{}, "Esc stop", "stop the animation"},
         Row{Pattern::of(Key::space), cmd::Pause{}, "Space pause", "pause, or go on"},
         Row{Pattern::letter(U'R'), cmd::Replay{}, "R replay", "replay from the first frame (KEY1, or a scene's frame 0)"}});
    add_graphics_rows(Context::animation, "end APCS; every file written so far stays");

    add(Context::quit_question,
        {Row{Pattern::letter(U'Y'), cmd::Yes{}, "", "end APCS; the path shown is not saved"},
         Row{Pattern::letter(U'N'), cmd::No{}, "", "go on adjusting"},
         Row{Pattern::of(Key::enter), cmd::No{}, "", "go on adjusting"}});
    add(Context::help_screen, {Row{Pattern::any_key(), cmd::Continue{}, "", "close this help"}});
    return table;
}

const std::vector<KeyBinding>& bindings()
{
    static const std::vector<KeyBinding> table = make_bindings();
    return table;
}

char32_t upper_case(char32_t character) { return character >= U'a' && character <= U'z' ? character - 32 : character; }

std::string_view key_name(Key key)
{
    switch (key) {
    case Key::character: return "a character";
    case Key::enter: return "Enter";
    case Key::escape: return "Esc";
    case Key::space: return "Space";
    case Key::left: return "Left";
    case Key::right: return "Right";
    case Key::up: return "Up";
    case Key::down: return "Down";
    case Key::backspace: return "Backspace";
    case Key::tab: return "Tab";
    case Key::back_tab: return "Shift-Tab";
    case Key::f1: return "F1";
    case Key::redraw: return "Ctrl-L";
    }
    return "";
}

} // namespace

bool KeyPattern::matches(const KeyEvent& event) const
{
    switch (kind) {
    case Kind::key: return event.key == key;
    case Kind::character: return event.key == Key::character && event.character == character;
    case Kind::letter: return event.key == Key::character && upper_case(event.character) == character;
    case Kind::printable: return event.key == Key::character && event.character >= 0x20;
    case Kind::any: return true;
    }
    return false;
}

std::span<const KeyBinding> key_bindings() { return bindings(); }

std::optional<Command> command_for(KeyContext context, const KeyEvent& event)
{
    for (const KeyBinding& binding : bindings()) {
        if (binding.context != context || !binding.pattern.matches(event))
            continue;
        Command command = binding.command;
        if (auto* typed = std::get_if<cmd::TypeCharacter>(&command); typed != nullptr && typed->character == 0)
            typed->character = event.character;
        return command;
    }
    return std::nullopt;
}

std::string key_help(KeyContext context)
{
    std::vector<std::string_view> shown;
    for (const KeyBinding& binding : bindings())
        if (binding.context == context && !binding.help.empty() &&
            std::find(shown.begin(), shown.end(), binding.help) == shown.end())
            shown.push_back(binding.help);
    std::string help;
    for (const std::string_view words : shown)
        help += (help.empty() ? "" : "  ") + std::string(words);
    return help;
}

std::string key_label(const KeyPattern& pattern)
{
    switch (pattern.kind) {
    case KeyPattern::Kind::key: return std::string(key_name(pattern.key));
    case KeyPattern::Kind::character:
    case KeyPattern::Kind::letter: {
        std::string label;
        append_utf8(label, pattern.character);
        return label;
    }
    case KeyPattern::Kind::printable: return "any character";
    case KeyPattern::Kind::any: return "any other key";
    }
    return "";
}

std::vector<std::string> key_help_lines(KeyContext context)
{
    // Keys of one meaning share a line, in the order the table first names the meaning.
    std::vector<std::pair<std::string_view, std::string>> lines;
    for (const KeyBinding& binding : bindings()) {
        if (binding.context != context || binding.meaning.empty())
            continue;
        const auto same = std::find_if(lines.begin(), lines.end(),
                                       [&](const auto& line) { return line.first == binding.meaning; });
        if (same == lines.end())
            lines.emplace_back(binding.meaning, key_label(binding.pattern));
        else
            same->second += ", " + key_label(binding.pattern);
    }
    std::vector<std::string> text;
    for (const auto& [meaning, keys] : lines) {
        std::string line = "  " + keys;
        line.resize(std::max<std::size_t>(line.size() + 2, 18), ' ');
        text.push_back(line + std::string(meaning));
    }
    return text;
}

CellGrid key_help_screen(std::string_view what, KeyContext context)
{
    constexpr int rows = text_screen_rows;
    CellGrid grid(text_screen_columns, rows);
    grid.put_text(0, 0, "APCS help - the keys of " + std::string(what));
    int row = 2;
    for (const std::string& line : key_help_lines(context))
        if (row < rows - 3)
            grid.put_text(0, row++, line);
    grid.put_text(0, rows - 3, "  Ctrl-L redraws the screen; Ctrl-C ends APCS at once (files written stay whole).");
    grid.put_text(0, rows - 1, "Any key closes this help.");
    return grid;
}

} // namespace apcs
