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
};

constexpr std::array<KeypadSequence, 5> keypad_sequence_table{{
    {"\033Ot", keypad_key_4},
    {"\033Ov", keypad_key_6},
    {"\033Ox", keypad_key_8},
    {"\033Or", keypad_key_2},
    {"\033OM", KEY_ENTER},
}};

} // namespace

std::span<const KeypadSequence> keypad_sequences() { return keypad_sequence_table; }

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
