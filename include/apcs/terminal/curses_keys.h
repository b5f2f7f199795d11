#pragma once

#include "apcs/session/key_event.h"

#include <cwchar>
#include <optional>
#include <span>

namespace apcs {

// Key codes of ours for the keypad's 2, 4, 6 and 8, which curses does not name. Above KEY_MAX
// (0777), and above the codes ncurses gives terminfo's extended key names (KEY_MAX + their
// index, a few hundred at most), below 0x10000 (ncurses keeps key codes in 16 bits).
inline constexpr int keypad_key_base = 0x1000;
inline constexpr int keypad_key_2 = keypad_key_base + 2;
inline constexpr int keypad_key_4 = keypad_key_base + 4;
inline constexpr int keypad_key_6 = keypad_key_base + 6;
inline constexpr int keypad_key_8 = keypad_key_base + 8;

// A sequence the keypad sends in application mode with NumLock off, and the curses key code that
// the terminal binds it to (define_key) where terminfo does not name it.
struct KeypadSequence {
    const char* sequence;
    int code;
};

// ESC O t = keypad_key_4, ESC O v = keypad_key_6, ESC O x = keypad_key_8, ESC O r = keypad_key_2,
// ESC O M = KEY_ENTER (SPEC §7.3).
std::span<const KeypadSequence> keypad_sequences();

// The key the session sees for what get_wch returned (`get_wch_result`: OK for a character,
// KEY_CODE_YES for a curses key code): arrows, Enter (CR, LF, KEY_ENTER), Space, Backspace (^H,
// DEL, KEY_BACKSPACE), Esc, the keypad's digits and any other printable character. nullopt for
// anything else (ERR, other control characters, keys the session has no use for). KEY_RESIZE is
// the caller's. Pure: uses the constants of <curses.h> only, so it is tested without ncurses.
std::optional<KeyEvent> key_event_from_curses(int get_wch_result, wint_t code);

} // namespace apcs
