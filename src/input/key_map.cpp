#include "apcs/input/key_map.h"

#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"

#include <algorithm>
#include <array>
#include <string_view>
#include <variant>
#include <vector>

namespace apcs {

namespace {

namespace cmd = command;

// The key map (SPEC §3, §7.3). In each context the first row that matches a key wins, the key line
// shows the rows' words in table order and the help screen their texts, a text once with all its
// keys; so rows shared by several contexts come after the rows of each of them.
constexpr auto key_map = [] {
    using enum KeyContext;
    using Pattern = KeyPattern;
    constexpr KeyContexts console_questions{yes_to_go_on, enter_to_go_on, any_key};
    constexpr KeyContexts graphics_steps{any_key_graphics, control_choice, region_pick, staff,
                                         waypoints,        adjust_again,   animation};
    // The steps of the path screen whose key line shows "K/T/G/O/Z/C view", and those with an undo.
    constexpr KeyContexts path_steps{control_choice, region_pick, staff, adjust_again};
    constexpr KeyContexts undo_steps{control_choice, staff, adjust_again};
    // Where q ends APCS at once: no path is being adjusted.
    constexpr KeyContexts quit_at_once{yes_to_go_on, enter_to_go_on, any_key, splitting, any_key_graphics};
    constexpr std::string_view quit_path = "end APCS without saving this path (asks first)";
    constexpr std::string_view quit_now = "end APCS; every file written so far stays";
    constexpr std::string_view moves_across = "move the point one step left, right";
    constexpr std::string_view moves_up = "move the point one step up, down the screen";
    constexpr std::string_view accepts_path = "accept the path: it is written back with its values";
    // clang-format off
    return std::to_array<KeyBinding>({
        // contexts, key pattern, command, key-line words, help text
        // Text prompts: every printable key is typed; Esc clears the line, and on an empty line
        // the session asks to quit (SPEC §7.3). {answer} is the prompt's empty answer.
        {{text_line}, Pattern::of(Key::enter),     cmd::SubmitLine{},     "", "answer; an empty line takes {answer}"},
        {{text_line}, Pattern::of(Key::backspace), cmd::EraseCharacter{}, "", "erase the last character"},
        {{text_line}, Pattern::of(Key::escape),    cmd::ClearLine{},      "", "clear the line; on an empty line, ask \"Quit APCS ? (Y/N)\""},
        {{text_line}, Pattern::of(Key::f1),        cmd::ShowHelp{},       "", "this help (so does the answer ? alone)"},
        // "=": the value typed on the message line, as at a text prompt.
        {{value_field},            Pattern::of(Key::enter),     cmd::SubmitLine{},        "Enter set",       "set the line to the typed value"},
        {{value_field},            Pattern::of(Key::backspace), cmd::EraseCharacter{},    "Backspace erase", "erase the last character"},
        {{value_field},            Pattern::of(Key::escape),    cmd::ClearLine{},         "Esc close",       "close the field; the value stays"},
        {{value_field},            Pattern::of(Key::f1),        cmd::ShowHelp{},          "",                "this help"},
        {{text_line, value_field}, Pattern::of(Key::space),     cmd::TypeCharacter{U' '}, "",                ""},
        {{text_line},              Pattern::printable(),        cmd::TypeCharacter{},     "",                "typed into the answer"},
        {{value_field},            Pattern::printable(),        cmd::TypeCharacter{},     "",                "typed into the value"},

        // The text console's questions and the quit question; q and "any key" are the last rows.
        {{yes_to_go_on},    Pattern::letter(U'Y'),    cmd::Yes{},      "", "adjust the next path"},
        {{enter_to_go_on},  Pattern::of(Key::enter),  cmd::Continue{}, "", "stop adjusting: surface fitting writes the in-betweens"},
        {console_questions, Pattern::of(Key::f1),     cmd::ShowHelp{}, "", "this help"},
        {console_questions, Pattern::exactly(U'?'),   cmd::ShowHelp{}, "", "this help"},
        {{splitting},       Pattern::of(Key::escape), cmd::Back{},     "", "stop the split: back to the KEY2 prompt (files written stay)"},
        {{quit_question},   Pattern::letter(U'Y'),    cmd::Yes{},      "", "end APCS (files written stay; a path being shaped is lost)"},
        {{quit_question},   Pattern::letter(U'N'),    cmd::No{},       "", "go back to the step as it was"},
        {{quit_question},   Pattern::of(Key::enter),  cmd::No{},       "", "go back to the step as it was"},
        {{quit_question},   Pattern::of(Key::escape), cmd::No{},       "", "go back to the step as it was"},
        {{help_screen},     Pattern::any_key(),       cmd::Continue{}, "", "close this help"},

        // Check_GorL_Control: the keypad's 8 and 2, or the arrows on them.
        {{control_choice}, Pattern::keypad(Key::up),   cmd::ChooseGlobal{},  "",            "global control: the staff adjusts the whole path"},
        {{control_choice}, Pattern::keypad(Key::down), cmd::ChooseLocal{},   "",            "local control: pick a region of control points"},
        {{control_choice}, Pattern::letter(U'W'),      cmd::OpenWaypoints{}, "W waypoints", "the waypoint editor: insert, delete and move control points"},
        // Scan_Control_Point: the message line says what 4/6 and Enter do.
        {{region_pick}, Pattern::keypad(Key::left),  cmd::ArrowMove{-1}, "", "the arrow to the previous control point"},
        {{region_pick}, Pattern::keypad(Key::right), cmd::ArrowMove{+1}, "", "the arrow to the next control point"},
        {{region_pick}, Pattern::of(Key::enter),     cmd::Accept{},      "", "pick the control point the arrow points at"},
        {{region_pick}, Pattern::of(Key::escape),    cmd::Back{},        "", "one step back"},
        // Ask_Adjusting: Y again; N or Enter accepts the path; other keys are not an answer.
        {{adjust_again}, Pattern::letter(U'Y'),   cmd::Yes{}, "", "adjust the path again"},
        {{adjust_again}, Pattern::letter(U'N'),   cmd::No{},  "", accepts_path},
        {{adjust_again}, Pattern::of(Key::enter), cmd::No{},  "", accepts_path},
        // Scan_Parameters / tnextpixel (thesis fig. 3.1.5).
        {{staff}, Pattern::keypad(Key::left),  cmd::StaffStep{-1},    "4/6 J/L step", "the value one step left, right"},
        {{staff}, Pattern::keypad(Key::right), cmd::StaffStep{+1},    "",             "the value one step left, right"},
        {{staff}, Pattern::letter(U'J'),       cmd::StaffStep{-3},    "",             "three steps left, right (Shift-J, Shift-L)"},
        {{staff}, Pattern::letter(U'L'),       cmd::StaffStep{+3},    "",             "three steps left, right (Shift-J, Shift-L)"},
        {{staff}, Pattern::exactly(U'='),      cmd::OpenValueField{}, "= type",       "type the value on the message line"},
        {{staff}, Pattern::of(Key::enter),     cmd::Accept{},         "Enter accept", "accept the value, go to the next line"},
        {{staff}, Pattern::of(Key::escape),    cmd::Keep{},           "Esc keep",     "leave the line as it was, go to the next"},
        // The path screen's undo and teaching overlays.
        {undo_steps, Pattern::letter(U'U'),      cmd::Undo{},            "U undo",     "undo the last change of this path"},
        {path_steps, Pattern::letter(U'K'),      cmd::ToggleKeyFrames{}, "K/T/G/O/Z/C view", "show or hide both key frames, dotted, beside the path"},
        {path_steps, Pattern::letter(U'T'),      cmd::ToggleTangents{},  "K/T/G/O/Z/C view", "tangents on/off: DD leaving (solid), DS arriving (dashed)"},
        {path_steps, Pattern::letter(U'G'),      cmd::ToggleLawGraph{},  "K/T/G/O/Z/C view", "law graph on/off: distance against frame in the span"},
        {path_steps, Pattern::letter(U'Z'),      cmd::Zoom{},            "K/T/G/O/Z/C view", "zoom x2, x4, x8 about the picked region, then back to fitted"},
        {path_steps, Pattern::letter(U'O'),      cmd::ToggleGhost{},     "K/T/G/O/Z/C view", "ghost on/off: the curve before the last change, dotted"},
        {path_steps, Pattern::letter(U'C'),      cmd::PinReference{},    "K/T/G/O/Z/C view", "compare: pin this curve as reference A (dashed), or unpin it"},
        {{staff},    Pattern::of(Key::tab),      cmd::ChoosePoint{+1},   "",           "the tangents' numbers of the next, previous control point"},
        {{staff},    Pattern::of(Key::back_tab), cmd::ChoosePoint{-1},   "",           "the tangents' numbers of the next, previous control point"},

        // The waypoint editor: the keypad moves the chosen control point in the screen's plane. Its
        // key line is full: K/T/G and q go to the help screen only.
        {{waypoints}, Pattern::of(Key::tab),       cmd::ChoosePoint{+1},     "Tab point",    "choose the next, previous control point"},
        {{waypoints}, Pattern::of(Key::back_tab),  cmd::ChoosePoint{-1},     "",             "choose the next, previous control point"},
        {{waypoints}, Pattern::exactly(U']'),      cmd::ChoosePoint{+1},     "",             "choose the next, previous control point"},
        {{waypoints}, Pattern::exactly(U'['),      cmd::ChoosePoint{-1},     "",             "choose the next, previous control point"},
        {{waypoints}, Pattern::keypad(Key::left),  cmd::MovePoint{-1, 0, 0}, "2468 +- move", moves_across},
        {{waypoints}, Pattern::keypad(Key::right), cmd::MovePoint{+1, 0, 0}, "",             moves_across},
        {{waypoints}, Pattern::keypad(Key::up),    cmd::MovePoint{0, +1, 0}, "",             moves_up},
        {{waypoints}, Pattern::keypad(Key::down),  cmd::MovePoint{0, -1, 0}, "",             moves_up},
        {{waypoints}, Pattern::letter(U'J'),       cmd::MovePoint{-3, 0, 0}, "",             "three steps left, right (Shift-J, Shift-L)"},
        {{waypoints}, Pattern::letter(U'L'),       cmd::MovePoint{+3, 0, 0}, "",             "three steps left, right (Shift-J, Shift-L)"},
        {{waypoints}, Pattern::exactly(U'+'),      cmd::MovePoint{0, 0, +1}, "",             "one step toward, away from the viewer"},
        {{waypoints}, Pattern::exactly(U'-'),      cmd::MovePoint{0, 0, -1}, "",             "one step toward, away from the viewer"},
        {{waypoints}, Pattern::letter(U'I'),       cmd::InsertPoint{},       "I/D ins/del",  "insert a control point after the chosen one, delete it"},
        {{waypoints}, Pattern::letter(U'D'),       cmd::DeletePoint{},       "",             "insert a control point after the chosen one, delete it"},
        {{waypoints}, Pattern::letter(U'U'),       cmd::Undo{},              "U undo",       "undo the last change in the editor"},
        {{waypoints}, Pattern::of(Key::enter),     cmd::Accept{},            "Enter keep",   "leave the editor keeping (Enter) or undoing (Esc) its changes"},
        {{waypoints}, Pattern::of(Key::escape),    cmd::Back{},              "Esc drop",     "leave the editor keeping (Enter) or undoing (Esc) its changes"},
        {{waypoints}, Pattern::letter(U'K'),       cmd::ToggleKeyFrames{},   "",             "show or hide both key frames, dotted, beside the path"},
        {{waypoints}, Pattern::letter(U'T'),       cmd::ToggleTangents{},    "",             "tangents on/off: DD leaving (solid), DS arriving (dashed)"},
        {{waypoints}, Pattern::letter(U'G'),       cmd::ToggleLawGraph{},    "",             "law graph on/off: distance against frame in the span"},
        {{waypoints}, Pattern::letter(U'O'),       cmd::ToggleGhost{},       "",             "ghost on/off: the curve before the last change, dotted"},
        {{waypoints}, Pattern::letter(U'C'),       cmd::PinReference{},      "",             "compare: pin this curve as reference A (dashed), or unpin it"},
        {{waypoints}, Pattern::letter(U'Z'),       cmd::Zoom{},              "",             "zoom x2, x4, x8 about the chosen point, then back"},

        // Showing_Animation.
        {{animation}, Pattern::of(Key::escape), cmd::StopAnimation{}, "Esc stop",    "stop the animation"},
        {{animation}, Pattern::of(Key::space),  cmd::Pause{},         "Space pause", "pause, or go on"},
        {{animation}, Pattern::letter(U'R'),    cmd::Replay{},        "R replay",    "replay from the first frame (KEY1, or a scene's frame 0)"},
        {{animation}, Pattern::exactly(U','),   cmd::StepFrame{-1},   ",. frame",    "pause and show the frame before, after"},
        {{animation}, Pattern::exactly(U'.'),   cmd::StepFrame{+1},   "",            "pause and show the frame before, after"},

        // Every step of graphics mode: help and a picture of the screen. A full key line leaves
        // "q quit" to the help screen.
        {graphics_steps,                              Pattern::exactly(U'?'), cmd::ShowHelp{},    "? help", "this help"},
        {graphics_steps,                              Pattern::of(Key::f1),   cmd::ShowHelp{},    "",       "this help"},
        {graphics_steps,                              Pattern::letter(U'P'),  cmd::SavePicture{}, "",       "write the screen as apcsNNN.png in the work folder"},
        // q is spelt in lower case everywhere (key line, help, manual), as less and htop spell it.
        {{control_choice, region_pick, adjust_again}, Pattern::letter(U'q'),  cmd::Quit{},        "q quit", quit_path},
        {{staff, waypoints},                          Pattern::letter(U'q'),  cmd::Quit{},        "",       quit_path},
        {{animation},                                 Pattern::letter(U'q'),  cmd::Quit{},        "q quit", quit_now},
        {quit_at_once,                                Pattern::letter(U'q'),  cmd::Quit{},        "",       quit_now},
        {{any_key, any_key_graphics},                 Pattern::any_key(),     cmd::Continue{},    "",       "go on"},
    });
    // clang-format on
}();

char32_t upper_case(char32_t character) { return character >= U'a' && character <= U'z' ? character - 32 : character; }

std::string character_label(char32_t character)
{
    std::string label;
    append_utf8(label, character);
    return label;
}

std::string_view key_name(Key key)
{
    const PhysicalKey* row = find_physical_key(key);
    return row != nullptr ? row->help_label : "a character";
}

// A help text with the prompt's empty answer in place of {answer}.
std::string help_text_for(std::string_view text, std::string_view empty_answer)
{
    constexpr std::string_view slot = "{answer}";
    std::string filled(text);
    if (const auto at = filled.find(slot); at != std::string::npos)
        filled.replace(at, slot.size(), empty_answer.empty() ? "the prompt's example answer" : empty_answer);
    return filled;
}

// The help column starts here; a line wider than 79 columns (the last one stays free) goes on
// below it, cut at a space.
constexpr std::size_t help_column = 18;

std::vector<std::string> screen_rows(std::string line)
{
    const auto width = static_cast<std::size_t>(text_screen_columns - 1);
    std::vector<std::string> rows;
    while (line.size() > width) {
        const auto space = line.rfind(' ', width);
        const auto cut = space != std::string::npos && space > help_column ? space : width;
        rows.push_back(line.substr(0, cut));
        line = std::string(help_column, ' ') + line.substr(line[cut] == ' ' ? cut + 1 : cut);
    }
    rows.push_back(line);
    return rows;
}

} // namespace

bool KeyPattern::matches(const KeyEvent& event) const
{
    switch (kind) {
    case Kind::key: return event.key == key;
    case Kind::character: return event.key == Key::character && event.character == character;
    case Kind::letter: return event.key == Key::character && upper_case(event.character) == upper_case(character);
    case Kind::keypad: return event.key == key || (event.key == Key::character && event.character == character);
    case Kind::printable: return event.key == Key::character && event.character >= 0x20;
    // Ctrl-L repaints the terminal wherever it is typed (the help screen says so): it is no
    // "any key" that closes a screen or goes on.
    case Kind::any: return event.key != Key::redraw;
    }
    return false;
}

std::span<const KeyBinding> key_bindings() { return key_map; }

std::optional<Command> command_for(KeyContext context, const KeyEvent& event)
{
    for (const KeyBinding& binding : key_map) {
        if (!binding.contexts.contains(context) || !binding.pattern.matches(event))
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
    for (const KeyBinding& binding : key_map)
        if (binding.contexts.contains(context) && !binding.key_line_words.empty() &&
            std::find(shown.begin(), shown.end(), binding.key_line_words) == shown.end())
            shown.push_back(binding.key_line_words);
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
    case KeyPattern::Kind::letter: return character_label(pattern.character);
    case KeyPattern::Kind::keypad: return character_label(pattern.character) + ", " + std::string(key_name(pattern.key));
    case KeyPattern::Kind::printable: return "any character";
    case KeyPattern::Kind::any: return "any other key";
    }
    return "";
}

std::vector<std::string> key_help_lines(KeyContext context, std::string_view empty_answer)
{
    // Keys of one meaning share a line, in the order the table first names the meaning.
    std::vector<std::pair<std::string_view, std::string>> lines;
    for (const KeyBinding& binding : key_map) {
        if (!binding.contexts.contains(context) || binding.help_text.empty())
            continue;
        const auto same = std::find_if(lines.begin(), lines.end(),
                                       [&](const auto& line) { return line.first == binding.help_text; });
        if (same == lines.end())
            lines.emplace_back(binding.help_text, key_label(binding.pattern));
        else
            same->second += ", " + key_label(binding.pattern);
    }
    std::vector<std::string> text;
    for (const auto& [meaning, keys] : lines) {
        std::string line = "  " + keys;
        line.resize(std::max<std::size_t>(line.size() + 2, help_column), ' ');
        for (std::string& row : screen_rows(line + help_text_for(meaning, empty_answer)))
            text.push_back(std::move(row));
    }
    return text;
}

namespace {

// Whether the help of `context` is opened over the path screen (its colour legend belongs there).
bool over_path_screen(KeyContext context)
{
    switch (context) {
    case KeyContext::control_choice:
    case KeyContext::region_pick:
    case KeyContext::staff:
    case KeyContext::value_field:
    case KeyContext::waypoints:
    case KeyContext::adjust_again: return true;
    default: return false;
    }
}

// SPEC §7.2.1's legend, each overlay's name in its own colour role, from `row` on (three rows).
void put_colour_legend(CellGrid& grid, int row)
{
    grid.put_text(0, row, "  Colours (NO_COLOR or --color never: one colour; the ghost dotted, A dashed):");
    int column = 2;
    ++row;
    for (const ColourRole role : colour_roles) {
        const std::string item = std::string(colour_role_name(role)) + " " + std::string(colour_name(role));
        if (column + static_cast<int>(item.size()) + 2 > grid.columns()) {
            column = 2;
            ++row;
        }
        grid.put_text(column, row, item, CellStyle::plain, role);
        column += static_cast<int>(item.size()) + 2;
    }
}

} // namespace

CellGrid key_help_screen(std::string_view what, KeyContext context, std::string_view empty_answer)
{
    constexpr int rows = text_screen_rows;
    constexpr int legend_rows = 4;
    CellGrid grid(text_screen_columns, rows);
    grid.put_text(0, 0, "APCS help - the keys of " + std::string(what));
    // Over the path screen the waypoint editor's seventeen key lines and the legend's four rows
    // fill every row between the title and the last two.
    constexpr int ctrl_keys_row = rows - 2;
    const int legend_row = over_path_screen(context) ? ctrl_keys_row - legend_rows : ctrl_keys_row;
    int row = over_path_screen(context) ? 1 : 2;
    for (const std::string& line : key_help_lines(context, empty_answer))
        if (row < legend_row)
            grid.put_text(0, row++, line);
    if (legend_row < ctrl_keys_row)
        put_colour_legend(grid, legend_row);
    grid.put_text(0, ctrl_keys_row, "  Ctrl-L redraws the screen; Ctrl-C ends APCS at once (every file stays whole).");
    grid.put_text(0, rows - 1, "Any key closes this help.");
    return grid;
}

std::string_view key_context_name(KeyContext context)
{
    switch (context) {
    case KeyContext::text_line: return "text_line";
    case KeyContext::yes_to_go_on: return "yes_to_go_on";
    case KeyContext::enter_to_go_on: return "enter_to_go_on";
    case KeyContext::any_key: return "any_key";
    case KeyContext::splitting: return "splitting";
    case KeyContext::any_key_graphics: return "any_key_graphics";
    case KeyContext::control_choice: return "control_choice";
    case KeyContext::region_pick: return "region_pick";
    case KeyContext::staff: return "staff";
    case KeyContext::value_field: return "value_field";
    case KeyContext::waypoints: return "waypoints";
    case KeyContext::adjust_again: return "adjust_again";
    case KeyContext::animation: return "animation";
    case KeyContext::quit_question: return "quit_question";
    case KeyContext::help_screen: return "help_screen";
    case KeyContext::finished: return "finished";
    }
    return "?";
}

bool stays_in_step(KeyContext context, const Command& command)
{
    const auto is = [&command]<typename... Kinds>(Kinds...) { return (std::holds_alternative<Kinds>(command) || ...); };
    using namespace command;
    switch (context) {
    case KeyContext::text_line:
    case KeyContext::value_field: return is(TypeCharacter{}, EraseCharacter{});
    case KeyContext::staff: return is(StaffStep{});
    case KeyContext::region_pick: return is(ArrowMove{});
    case KeyContext::waypoints: return is(ChoosePoint{}, MovePoint{}, InsertPoint{}, DeletePoint{}, Undo{}, Zoom{});
    default: return false;
    }
}

} // namespace apcs
