#pragma once

#include <array>
#include <string_view>

// The keys the session knows besides printable characters (SPEC §3, §7.3), one row each: a new key
// is a row here and nothing else. Columns:
//   enumerator        its name in `Key`
//   script name       its token in a key script (`--keys`, `--record`); the script's error text
//                     lists them all in this order
//   help label        how the help screen names it
//   keypad digit      what the same keypad key types with NumLock on (0: none); a binding written
//                     KeyPattern::keypad(Key::left) means the arrow and its digit alike
//   curses key codes  what get_wch returns for it with KEY_CODE_YES, at most 2; the escape sequences
//                     are bound to the first
//   characters        what get_wch returns for it as a character, at most 2
//   escape sequences  what a terminal may send for it where its terminfo names another sequence,
//                     bound with define_key, at most 3
// The last three columns name <curses.h> constants. Only src/terminal/curses_keys.cpp expands them,
// so the core reads this table without curses. A macro, because C++20 has no other way to make an
// enumeration and the rows that describe its values one list.
// clang-format off
#define APCS_PHYSICAL_KEYS(ROW)                                                                               \
    /*  enumerator  script name  help label   keypad  curses key codes  characters    escape sequences */      \
    ROW(enter,      "ENTER",     "Enter",     0,      (KEY_ENTER),      ('\r', '\n'), ("\033OM"))              \
    ROW(escape,     "ESC",       "Esc",       0,      (),               (27),         ())                      \
    ROW(space,      "SPACE",     "Space",     0,      (),               (' '),        ())                      \
    ROW(left,       "LEFT",      "Left",      U'4',   (KEY_LEFT),       (),           ("\033[D", "\033OD"))    \
    ROW(right,      "RIGHT",     "Right",     U'6',   (KEY_RIGHT),      (),           ("\033[C", "\033OC"))    \
    ROW(up,         "UP",        "Up",        U'8',   (KEY_UP),         (),           ("\033[A", "\033OA"))    \
    ROW(down,       "DOWN",      "Down",      U'2',   (KEY_DOWN),       (),           ("\033[B", "\033OB"))    \
    ROW(backspace,  "BACKSPACE", "Backspace", 0,      (KEY_BACKSPACE),  (8, 127),     ())                      \
    ROW(tab,        "TAB",       "Tab",       0,      (),               ('\t'),       ())                      \
    ROW(back_tab,   "BTAB",      "Shift-Tab", 0,      (KEY_BTAB),       (),           ("\033[Z"))              \
    ROW(f1,         "F1",        "F1",        0,      (KEY_F(1)),       (),           ("\033OP", "\033[11~", "\033[[A")) \
    ROW(redraw,     "CTRL-L",    "Ctrl-L",    0,      (),               (12),         ())                      \
    ROW(page_down,  "PGDN",      "PgDn",      0,      (KEY_NPAGE),      (),           ("\033[6~"))            \
    ROW(page_up,    "PGUP",      "PgUp",      0,      (KEY_PPAGE),      (),           ("\033[5~"))            \
    ROW(home,       "HOME",      "Home",      0,      (KEY_HOME),       (),           ("\033[H", "\033[1~", "\033OH"))
// clang-format on

namespace apcs {

#define APCS_KEY_ENUMERATOR(enumerator, ...) enumerator,
// A key as the session sees it: the terminal maps digits, arrows and the keypad to these
// (SPEC §7.3); `character` carries any other printable key.
enum class Key { character, APCS_PHYSICAL_KEYS(APCS_KEY_ENUMERATOR) };
#undef APCS_KEY_ENUMERATOR

// The columns of a row of APCS_PHYSICAL_KEYS that the session reads.
struct PhysicalKey {
    Key key;
    std::string_view script_name;
    std::string_view help_label;
    char32_t keypad_digit;
};

#define APCS_PHYSICAL_KEY(enumerator, script_name, help_label, keypad_digit, ...)                             \
    PhysicalKey{Key::enumerator, script_name, help_label, keypad_digit},
inline constexpr std::array physical_keys{APCS_PHYSICAL_KEYS(APCS_PHYSICAL_KEY)};
#undef APCS_PHYSICAL_KEY

// The row of `key`; nullptr for Key::character, which is no physical key of its own.
constexpr const PhysicalKey* find_physical_key(Key key)
{
    for (const PhysicalKey& row : physical_keys)
        if (row.key == key)
            return &row;
    return nullptr;
}

} // namespace apcs
