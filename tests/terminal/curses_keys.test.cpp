#include "apcs/formats/key_script.h"
#include "apcs/terminal/curses_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <iterator>
#include <optional>
#include <span>
#include <string>

// The constants only: this test binary does not link ncurses.
#include <curses.h>

using namespace apcs;

namespace {

std::string shown(const std::optional<KeyEvent>& event)
{
    if (!event)
        return "nothing";
    if (event->key == Key::character)
        return "typed U+" + std::to_string(static_cast<unsigned long>(event->character));
    std::string token = format_key_script({*event});
    if (token.ends_with('\n'))
        token.pop_back();
    return token;
}

struct Row {
    const char* what;
    int get_wch_result;
    wint_t code;
    std::optional<KeyEvent> expected;
};

KeyEvent of(Key key) { return KeyEvent::of(key); }
KeyEvent typed(char32_t character) { return KeyEvent::typed(character); }

} // namespace

TEST_CASE("Curses key codes and characters become the session's keys", "[terminal]")
{
    const Row rows[] = {
        {"left arrow", KEY_CODE_YES, KEY_LEFT, of(Key::left)},
        {"right arrow", KEY_CODE_YES, KEY_RIGHT, of(Key::right)},
        {"up arrow", KEY_CODE_YES, KEY_UP, of(Key::up)},
        {"down arrow", KEY_CODE_YES, KEY_DOWN, of(Key::down)},
        {"keypad Enter", KEY_CODE_YES, KEY_ENTER, of(Key::enter)},
        {"Backspace key", KEY_CODE_YES, KEY_BACKSPACE, of(Key::backspace)},
        {"keypad 4 (ESC O t)", KEY_CODE_YES, keypad_key_4, typed(U'4')},
        {"keypad 6 (ESC O v)", KEY_CODE_YES, keypad_key_6, typed(U'6')},
        {"keypad 8 (ESC O x)", KEY_CODE_YES, keypad_key_8, typed(U'8')},
        {"keypad 2 (ESC O r)", KEY_CODE_YES, keypad_key_2, typed(U'2')},
        {"CR", OK, '\r', of(Key::enter)},
        {"LF", OK, '\n', of(Key::enter)},
        {"space", OK, ' ', of(Key::space)},
        {"^H", OK, 8, of(Key::backspace)},
        {"DEL", OK, 127, of(Key::backspace)},
        {"Esc", OK, 27, of(Key::escape)},
        {"a digit", OK, '8', typed(U'8')},
        {"a letter", OK, 'J', typed(U'J')},
        {"a question mark", OK, '?', typed(U'?')},
        {"a tilde", OK, '~', typed(U'~')},
        {"a character beyond ASCII", OK, 0xE9, typed(U'\u00E9')},
        {"a character with a key code's number", OK, KEY_LEFT, typed(static_cast<char32_t>(KEY_LEFT))},
        {"a wide character", OK, 0x2800, typed(U'\u2800')},
        {"Tab", OK, '\t', of(Key::tab)},
        {"Shift-Tab", KEY_CODE_YES, KEY_BTAB, of(Key::back_tab)},
        {"F1", KEY_CODE_YES, KEY_F(1), of(Key::f1)},
        {"Ctrl-L", OK, 12, of(Key::redraw)},
        {"F2", KEY_CODE_YES, KEY_F(2), std::nullopt},
        {"a key code with Ctrl-L's number", KEY_CODE_YES, 12, std::nullopt},
        {"a character with Shift-Tab's number", OK, KEY_BTAB, typed(static_cast<char32_t>(KEY_BTAB))},
        {"^A", OK, 1, std::nullopt},
        {"NUL", OK, 0, std::nullopt},
        {"Home", KEY_CODE_YES, KEY_HOME, of(Key::home)},
        {"PgDn", KEY_CODE_YES, KEY_NPAGE, of(Key::page_down)},
        {"PgUp", KEY_CODE_YES, KEY_PPAGE, of(Key::page_up)},
        {"End", KEY_CODE_YES, KEY_END, std::nullopt},
        {"a key code with a character's number", KEY_CODE_YES, 'a', std::nullopt},
        {"a key code of ours unbound", KEY_CODE_YES, keypad_key_base, std::nullopt},
        {"nothing read", ERR, 0, std::nullopt},
        {"nothing read, a stale character", ERR, 'a', std::nullopt},
    };
    for (const Row& row : rows) {
        const std::optional<KeyEvent> actual = key_event_from_curses(row.get_wch_result, row.code);
        INFO(row.what << ": got " << shown(actual) << ", expected " << shown(row.expected));
        CHECK(actual == row.expected);
    }
}

TEST_CASE("Sequences terminfo may not name are bound: keypad, both arrow modes, Shift-Tab, F1, PgDn, PgUp, Home", "[terminal]")
{
    struct SequenceRow {
        std::string sequence;
        KeyEvent expected;
    };
    const SequenceRow rows[] = {
        {"\033Ot", typed(U'4')},       {"\033Ov", typed(U'6')},       {"\033Ox", typed(U'8')},
        {"\033Or", typed(U'2')},       {"\033OM", of(Key::enter)},    {"\033[A", of(Key::up)},
        {"\033[B", of(Key::down)},     {"\033[C", of(Key::right)},    {"\033[D", of(Key::left)},
        {"\033OA", of(Key::up)},       {"\033OB", of(Key::down)},     {"\033OC", of(Key::right)},
        {"\033OD", of(Key::left)},     {"\033[Z", of(Key::back_tab)}, {"\033OP", of(Key::f1)},
        {"\033[11~", of(Key::f1)},     {"\033[[A", of(Key::f1)},     {"\033[6~", of(Key::page_down)},
        {"\033[5~", of(Key::page_up)}, {"\033[H", of(Key::home)},    {"\033[1~", of(Key::home)},
        {"\033OH", of(Key::home)},
    };
    const std::span<const KeySequence> sequences = key_sequences();
    REQUIRE(sequences.size() == std::size(rows));
    for (const SequenceRow& row : rows) {
        INFO("sequence ESC " << row.sequence.substr(1));
        const auto bound =
            std::ranges::find_if(sequences, [&](const KeySequence& entry) { return entry.sequence == row.sequence; });
        REQUIRE(bound != sequences.end());
        CHECK(key_event_from_curses(KEY_CODE_YES, static_cast<wint_t>(bound->code)) == row.expected);
    }
}

TEST_CASE("What follows an unmatched Esc at once is a sequence to drop, or keys of their own", "[terminal]")
{
    struct TailRow {
        std::u32string after_escape;
        EscapeTail expected;
    };
    const TailRow rows[] = {
        {U"", EscapeTail::unfinished},
        {U"[", EscapeTail::unfinished},
        {U"[1", EscapeTail::unfinished},
        {U"[1;5", EscapeTail::unfinished},
        {U"[1;5D", EscapeTail::sequence},    // Ctrl-Left
        {U"[15~", EscapeTail::sequence},     // F5
        {U"[200~", EscapeTail::sequence},    // bracketed paste
        {U"[D", EscapeTail::sequence},       // left arrow, where nothing bound it
        {U"[?1;2c", EscapeTail::sequence},   // a device attribute report
        {U"[1 q", EscapeTail::sequence},     // an intermediate byte, then the final one
        {U"[1 ", EscapeTail::unfinished},
        {U"[1 2", EscapeTail::broken},       // a parameter after an intermediate
        {U"[1\u00e9", EscapeTail::broken},   // a character no sequence holds
        {U"[\u001b", EscapeTail::broken},    // Esc again
        {U"O", EscapeTail::unfinished},
        {U"Oq", EscapeTail::sequence},       // the keypad's 1 in application mode
        {U"O\u001b", EscapeTail::broken},
        {U"]0;title", EscapeTail::unfinished}, // an OSC string (a window title) not yet ended
        {U"]0;title\a", EscapeTail::sequence}, // ended by BEL: dropped whole, never typed
        {U"]0;title\u001b", EscapeTail::unfinished},
        {U"]0;title\u001b\\", EscapeTail::sequence}, // ended by ST (ESC \\)
        {U"]0;ti\u001bx", EscapeTail::broken},
        {U"P1$r0m\u001b\\", EscapeTail::sequence},  // a DCS report
        {U"_Gi=1;OK\u001b\\", EscapeTail::sequence}, // a kitty graphics reply (APC)
        {U"]0;ab\u0018", EscapeTail::sequence},      // CAN cancels the string
        {U"\u001b", EscapeTail::keys},       // Esc, Esc
        {U"a", EscapeTail::keys},            // Esc, then a letter (Alt-a)
        {U"4", EscapeTail::keys},
        {U"\u00e9", EscapeTail::keys},
    };
    for (const TailRow& row : rows) {
        std::string shown_tail;
        for (const char32_t c : row.after_escape)
            shown_tail += c >= 0x20 && c < 0x7F ? std::string(1, static_cast<char>(c)) : "U+" + std::to_string(c);
        INFO("ESC " << shown_tail);
        CHECK(escape_tail(row.after_escape) == row.expected);
    }
}
