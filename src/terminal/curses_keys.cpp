#include "apcs/terminal/curses_keys.h"

#include <algorithm>
#include <array>

#include <curses.h>

namespace apcs {

static_assert(keypad_key_base > KEY_MAX + 0x200 && keypad_key_8 < 0x10000);

namespace {

// What get_wch gives and the key the session sees: `key_code` when get_wch said KEY_CODE_YES
// (a curses key code), else a character. Any other printable character is typed as itself.
struct CursesKey {
    bool key_code;
    wint_t code;
    KeyEvent event;
};

constexpr std::array curses_keys{
    CursesKey{true, KEY_LEFT, {Key::left, 0}},
    CursesKey{true, KEY_RIGHT, {Key::right, 0}},
    CursesKey{true, KEY_UP, {Key::up, 0}},
    CursesKey{true, KEY_DOWN, {Key::down, 0}},
    CursesKey{true, KEY_ENTER, {Key::enter, 0}},
    CursesKey{true, KEY_BACKSPACE, {Key::backspace, 0}},
    CursesKey{true, KEY_BTAB, {Key::back_tab, 0}},
    CursesKey{true, KEY_F(1), {Key::f1, 0}},
    CursesKey{true, keypad_key_4, {Key::character, U'4'}},
    CursesKey{true, keypad_key_6, {Key::character, U'6'}},
    CursesKey{true, keypad_key_8, {Key::character, U'8'}},
    CursesKey{true, keypad_key_2, {Key::character, U'2'}},
    CursesKey{false, '\r', {Key::enter, 0}},
    CursesKey{false, '\n', {Key::enter, 0}},
    CursesKey{false, ' ', {Key::space, 0}},
    CursesKey{false, 8, {Key::backspace, 0}},
    CursesKey{false, 127, {Key::backspace, 0}},
    CursesKey{false, 27, {Key::escape, 0}},
    CursesKey{false, '\t', {Key::tab, 0}},
    CursesKey{false, 12, {Key::redraw, 0}}, // Ctrl-L
};

constexpr std::array key_sequence_table{
    KeySequence{"\033Ot", keypad_key_4},
    KeySequence{"\033Ov", keypad_key_6},
    KeySequence{"\033Ox", keypad_key_8},
    KeySequence{"\033Or", keypad_key_2},
    KeySequence{"\033OM", KEY_ENTER},
    KeySequence{"\033[A", KEY_UP},
    KeySequence{"\033[B", KEY_DOWN},
    KeySequence{"\033[C", KEY_RIGHT},
    KeySequence{"\033[D", KEY_LEFT},
    KeySequence{"\033OA", KEY_UP},
    KeySequence{"\033OB", KEY_DOWN},
    KeySequence{"\033OC", KEY_RIGHT},
    KeySequence{"\033OD", KEY_LEFT},
    KeySequence{"\033[Z", KEY_BTAB},
    KeySequence{"\033OP", KEY_F(1)},
    KeySequence{"\033[11~", KEY_F(1)},
    KeySequence{"\033[[A", KEY_F(1)},
};

} // namespace

std::span<const KeySequence> key_sequences() { return key_sequence_table; }

EscapeTail escape_tail(std::u32string_view after_escape)
{
    if (after_escape.empty())
        return EscapeTail::unfinished;
    const auto within = [](char32_t c, char32_t low, char32_t high) { return c >= low && c <= high; };
    if (after_escape.front() == U'O') {
        // SS3: one character more.
        if (after_escape.size() == 1)
            return EscapeTail::unfinished;
        return within(after_escape[1], 0x20, 0x7E) ? EscapeTail::sequence : EscapeTail::broken;
    }
    if (after_escape.front() != U'[')
        return EscapeTail::keys;
    // CSI (ECMA-48): parameter bytes 0x30-0x3F, then intermediate bytes 0x20-0x2F, then a final
    // byte 0x40-0x7E.
    bool intermediate = false;
    for (const char32_t c : after_escape.substr(1)) {
        if (within(c, 0x40, 0x7E))
            return EscapeTail::sequence;
        if (within(c, 0x30, 0x3F) && !intermediate)
            continue;
        if (within(c, 0x20, 0x2F)) {
            intermediate = true;
            continue;
        }
        return EscapeTail::broken;
    }
    return EscapeTail::unfinished;
}

std::optional<KeyEvent> key_event_from_curses(int get_wch_result, wint_t code)
{
    if (get_wch_result != OK && get_wch_result != KEY_CODE_YES)
        return std::nullopt;
    const bool key_code = get_wch_result == KEY_CODE_YES;
    const auto* found = std::find_if(curses_keys.begin(), curses_keys.end(), [&](const CursesKey& entry) {
        return entry.key_code == key_code && entry.code == code;
    });
    if (found != curses_keys.end())
        return found->event;
    if (!key_code && code >= 0x20)
        return KeyEvent::typed(static_cast<char32_t>(code));
    return std::nullopt;
}

} // namespace apcs
