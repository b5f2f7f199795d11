#include "apcs/terminal/curses_keys.h"

#include <algorithm>
#include <array>

#include <curses.h>

namespace apcs {

static_assert(keypad_key_base > KEY_MAX + 0x200 && keypad_key_8 < 0x10000);

namespace {

// What get_wch gives for a row of APCS_PHYSICAL_KEYS (physical_key.h): its curses columns, 0 (or
// nullptr) filling the slots a row leaves empty.
struct CursesKey {
    Key key;
    std::array<int, 2> key_codes;
    std::array<wint_t, 2> characters;
    std::array<const char*, 3> sequences;
};

#define APCS_LIST(...) __VA_ARGS__
#define APCS_CURSES_KEY(enumerator, script_name, help_label, keypad_digit, key_codes, characters, sequences)   \
    CursesKey{Key::enumerator, {APCS_LIST key_codes}, {APCS_LIST characters}, {APCS_LIST sequences}},
constexpr std::array curses_keys{APCS_PHYSICAL_KEYS(APCS_CURSES_KEY)};
#undef APCS_CURSES_KEY
#undef APCS_LIST

// The keypad's digits in application mode, which terminfo does not name: they type their digit.
struct KeypadDigit {
    const char* sequence;
    int code;
    char32_t digit;
};

constexpr std::array keypad_digits{
    KeypadDigit{"\033Ot", keypad_key_4, U'4'},
    KeypadDigit{"\033Ov", keypad_key_6, U'6'},
    KeypadDigit{"\033Ox", keypad_key_8, U'8'},
    KeypadDigit{"\033Or", keypad_key_2, U'2'},
};

constexpr std::size_t sequence_count()
{
    std::size_t count = keypad_digits.size();
    for (const CursesKey& row : curses_keys)
        for (const char* sequence : row.sequences)
            count += sequence != nullptr ? 1 : 0;
    return count;
}

// A row's sequences are bound to its first key code: a row with sequences needs one.
constexpr bool sequences_have_a_key_code()
{
    return std::ranges::all_of(curses_keys, [](const CursesKey& row) {
        return row.sequences[0] == nullptr || row.key_codes[0] != 0;
    });
}
static_assert(sequences_have_a_key_code());

constexpr auto key_sequence_table = [] {
    std::array<KeySequence, sequence_count()> table{};
    std::size_t next = 0;
    for (const KeypadDigit& keypad : keypad_digits)
        table[next++] = {keypad.sequence, keypad.code};
    for (const CursesKey& row : curses_keys)
        for (const char* sequence : row.sequences)
            if (sequence != nullptr)
                table[next++] = {sequence, row.key_codes[0]};
    return table;
}();

// The key of a curses key code: a physical key's, or a keypad digit typed.
std::optional<KeyEvent> key_of_code(wint_t code)
{
    for (const CursesKey& row : curses_keys)
        if (std::ranges::find(row.key_codes, static_cast<int>(code)) != row.key_codes.end())
            return KeyEvent::of(row.key);
    for (const KeypadDigit& keypad : keypad_digits)
        if (static_cast<int>(code) == keypad.code)
            return KeyEvent::typed(keypad.digit);
    return std::nullopt;
}

// The key of a character: a physical key's (Enter for CR), else the character typed if printable.
std::optional<KeyEvent> key_of_character(wint_t code)
{
    for (const CursesKey& row : curses_keys)
        if (std::ranges::find(row.characters, code) != row.characters.end())
            return KeyEvent::of(row.key);
    if (code >= 0x20)
        return KeyEvent::typed(static_cast<char32_t>(code));
    return std::nullopt;
}

// The text of an OSC, DCS or APC string (a window title a terminal reports, ESC ] 0;title BEL): any
// characters up to BEL or the string terminator ESC \; CAN or SUB cancels it (ECMA-48 8.3.89).
EscapeTail control_string_tail(std::u32string_view text)
{
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == U'\a' || text[i] == U'\x18' || text[i] == U'\x1a')
            return EscapeTail::sequence;
        if (text[i] == U'\x1b')
            return i + 1 == text.size() ? EscapeTail::unfinished
                                        : text[i + 1] == U'\\' ? EscapeTail::sequence : EscapeTail::broken;
    }
    return EscapeTail::unfinished;
}

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
    if (after_escape.front() == U']' || after_escape.front() == U'P' || after_escape.front() == U'_')
        return control_string_tail(after_escape.substr(1));
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
    // 0 fills a row's empty slots, and is no key either way (NUL).
    if (code == 0)
        return std::nullopt;
    if (get_wch_result == KEY_CODE_YES)
        return key_of_code(code);
    if (get_wch_result == OK)
        return key_of_character(code);
    return std::nullopt;
}

} // namespace apcs
