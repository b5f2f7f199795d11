#pragma once

#include "apcs/formats/key_event.h"

#include <cwchar>
#include <optional>
#include <span>
#include <string_view>

namespace apcs {

// Key codes of ours for the keypad's 2, 4, 6 and 8, which curses does not name. Above KEY_MAX
// (0777), and above the codes ncurses gives terminfo's extended key names (KEY_MAX + their
// index, a few hundred at most), below 0x10000 (ncurses keeps key codes in 16 bits).
inline constexpr int keypad_key_base = 0x1000;
inline constexpr int keypad_key_2 = keypad_key_base + 2;
inline constexpr int keypad_key_4 = keypad_key_base + 4;
inline constexpr int keypad_key_6 = keypad_key_base + 6;
inline constexpr int keypad_key_8 = keypad_key_base + 8;

// A sequence a terminal may send for a key while its terminfo entry names another one, and the
// curses key code the terminal binds it to (define_key) where terminfo does not name the sequence.
struct KeySequence {
    const char* sequence;
    int code;
};

// The keypad's digits in application mode (ESC O t = keypad_key_4, ESC O v = keypad_key_6,
// ESC O x = keypad_key_8, ESC O r = keypad_key_2), then the escape sequences of the physical keys'
// rows (physical_key.h), each bound to its row's first curses key code: the arrows in both
// cursor-key modes (ESC [ A and ESC O A: terminals that ignore the application mode, the keypad's
// arrows with NumLock off), the keypad's Enter (ESC O M), Shift-Tab (ESC [ Z) and F1 (ESC O P,
// ESC [ 1 1 ~, the Linux console's ESC [ [ A). SPEC §7.3.
std::span<const KeySequence> key_sequences();

// What the characters that follow an Esc at once make, when ncurses returned the Esc alone because
// they matched no key it knows (SPEC §7.3: a sequence is never typed into a prompt):
// - `unfinished`: they may still grow into an escape sequence (CSI: ESC [, parameters and
//   intermediates; SS3: ESC O; an OSC, DCS or APC string: ESC ], ESC P, ESC _ and its text);
// - `sequence`: a whole sequence (CSI up to its final byte; SS3 and one printable character; a
//   string up to BEL or ESC \), the key of a terminal APCS does not know, or a report such as a
//   window title: dropped, Esc included;
// - `broken`: a sequence begun, then a character that no sequence holds: the sequence is dropped,
//   Esc included, and that last character is a key of its own;
// - `keys`: no sequence at all (ESC and a letter, ESC ESC): the Esc is a key, and so are they.
enum class EscapeTail { unfinished, sequence, broken, keys };
EscapeTail escape_tail(std::u32string_view after_escape);

// The key the session sees for what get_wch returned (`get_wch_result`: OK for a character,
// KEY_CODE_YES for a curses key code): a physical key by its row's curses key codes and characters
// (physical_key.h: arrows, Enter as CR, LF or KEY_ENTER, Backspace as ^H, DEL or KEY_BACKSPACE,
// Ctrl-L and the rest), the keypad's digits typed, and any other printable character typed.
// nullopt for anything else (ERR, other control characters, keys the session has no use for).
// KEY_RESIZE is the caller's. Pure: uses the constants of <curses.h> only, so it is tested without
// ncurses.
std::optional<KeyEvent> key_event_from_curses(int get_wch_result, wint_t code);

} // namespace apcs
