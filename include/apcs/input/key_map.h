#pragma once

#include "apcs/raster/cell_grid.h"
#include "apcs/input/command.h"
#include "apcs/formats/key_event.h"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// Where the keys are read: each step of the session listens in one of these contexts.
enum class KeyContext {
    text_line,      // a text prompt: every printable key is typed text
    yes_to_go_on,   // "Press 'Y' to adjust the next path !"
    enter_to_go_on, // "Press <ENTER> to Stop the work !"
    any_key,        // "Press any key …" on the text console
    splitting,      // the split writing its path files: Esc stops it
    any_key_graphics, // "Press any key …" in graphics mode (after the animation)
    control_choice, // Check_GorL_Control
    region_pick,    // Scan_Control_Point
    staff,          // Scan_Parameters
    value_field,    // "=" on a staff line: the value typed on the message line
    waypoints,      // the waypoint editor (W at the 8/2 choice)
    adjust_again,   // Ask_Adjusting: Y again, anything else accepts
    animation,      // Showing_Animation
    quit_question,  // "Quit without saving this path ? (Y/N)", "Quit APCS ? (Y/N)"
    help_screen,    // the help screen: any key closes it
    finished,       // nothing is read
};

// The context's name as the enum spells it ("value_field"), for the printed charts.
std::string_view key_context_name(KeyContext context);

// Whether `command`, met in `context`, is known to leave the step where it is: typing a line, a
// staff step, the region's arrow, a waypoint edit. A headless transcript prints each step's last
// screen, the one before the key that ends it: it draws a screen only before a key this does not
// vouch for. False says nothing (the command may end its step or not).
bool stays_in_step(KeyContext context, const Command& command);

// The contexts a binding holds in.
class KeyContexts {
public:
    constexpr KeyContexts(std::initializer_list<KeyContext> contexts)
    {
        for (const KeyContext context : contexts)
            m_members |= bit(context);
    }
    constexpr bool contains(KeyContext context) const { return (m_members & bit(context)) != 0; }

private:
    static constexpr std::uint32_t bit(KeyContext context) { return std::uint32_t{1} << static_cast<int>(context); }
    std::uint32_t m_members = 0;
};
static_assert(static_cast<int>(KeyContext::finished) < 32, "KeyContexts holds a context in a bit of 32");

// Which keys a binding matches. The terminal gives a keypad digit and an arrow as different keys
// (at a text prompt 4 is typed and Left does nothing); where they mean the same (SPEC §7.3: digits
// 8/2/4/6 and the arrows are equal) one `keypad` pattern matches both.
struct KeyPattern {
    enum class Kind { key, character, letter, keypad, printable, any };
    Kind kind = Kind::any;
    Key key = Key::character;
    char32_t character = 0;

    static constexpr KeyPattern of(Key key) { return {Kind::key, key, 0}; }
    // Exactly this character (digits).
    static constexpr KeyPattern exactly(char32_t character) { return {Kind::character, Key::character, character}; }
    // This letter in either case (J is Shift-J on the PC keyboard; j works too), labelled on the
    // help screen in the case given (`q` as the key line and the manual spell it).
    static constexpr KeyPattern letter(char32_t label) { return {Kind::letter, Key::character, label}; }
    // An arrow, or the digit the same keypad key types with NumLock on (Left and 4).
    static constexpr KeyPattern keypad(Key arrow) { return {Kind::keypad, arrow, find_physical_key(arrow)->keypad_digit}; }
    // Any printable character (typed text).
    static constexpr KeyPattern printable() { return {Kind::printable, Key::character, 0}; }
    static constexpr KeyPattern any_key() { return {Kind::any, Key::character, 0}; }

    bool matches(const KeyEvent& event) const;
};

// One row of the key map: in `contexts`, a key matching `pattern` means `command`. `key_line_words`
// are the row's words on the key line of graphics mode (rows that share words are shown once;
// empty: not shown); `help_text` is what the help screen says of the key (empty: not shown).
struct KeyBinding {
    KeyContexts contexts;
    KeyPattern pattern;
    Command command;
    std::string_view key_line_words;
    std::string_view help_text;
};

// The whole key map (SPEC §3, §7.3), in the order it is searched: the first matching row wins.
std::span<const KeyBinding> key_bindings();

// What `event` means in `context`, or nullopt when the key means nothing there. A typed character's
// command carries the character.
std::optional<Command> command_for(KeyContext context, const KeyEvent& event);

// The key line of a context: its rows' help words, each once, in table order, two spaces apart.
std::string key_help(KeyContext context);

// The name of the keys a pattern matches, as the help screen writes it: "4", "Left", "4, Left", "J",
// "Enter".
std::string key_label(const KeyPattern& pattern);

// The help screen's lines for a context: every key and what it means, keys of the same meaning on
// one line ("4, Left    one step to the left"), a meaning too wide for 80 columns going on below.
// At a text prompt `empty_answer` is the answer an empty line takes there, which Enter's line names
// ("an empty line takes key1.dat"); empty, it says "the prompt's example answer".
std::vector<std::string> key_help_lines(KeyContext context, std::string_view empty_answer = {});

// The help screen (80x24 text): "APCS help - the keys of WHAT", the key_help_lines of `context`,
// and how to close it.
CellGrid key_help_screen(std::string_view what, KeyContext context, std::string_view empty_answer = {});

} // namespace apcs
