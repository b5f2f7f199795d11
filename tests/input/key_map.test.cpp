#include "apcs/formats/key_script.h"
#include "apcs/input/key_map.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>
#include <vector>

using namespace apcs;
namespace cmd = apcs::command;

namespace {

KeyEvent ch(char32_t c) { return KeyEvent::typed(c); }
KeyEvent key(Key k) { return KeyEvent::of(k); }

constexpr KeyContext all_contexts[] = {
    KeyContext::text_line,    KeyContext::yes_to_go_on, KeyContext::enter_to_go_on,   KeyContext::any_key,
    KeyContext::splitting,    KeyContext::any_key_graphics, KeyContext::control_choice, KeyContext::region_pick,
    KeyContext::staff,        KeyContext::value_field,  KeyContext::waypoints,        KeyContext::adjust_again,
    KeyContext::animation,    KeyContext::quit_question, KeyContext::help_screen,     KeyContext::finished,
};

// The keys a pattern names, one event each (none for the patterns of any key or any character).
std::vector<KeyEvent> examples_of(const KeyPattern& pattern)
{
    switch (pattern.kind) {
    case KeyPattern::Kind::key: return {KeyEvent::of(pattern.key)};
    case KeyPattern::Kind::character:
    case KeyPattern::Kind::letter: return {KeyEvent::typed(pattern.character)};
    case KeyPattern::Kind::keypad: return {KeyEvent::of(pattern.key), KeyEvent::typed(pattern.character)};
    case KeyPattern::Kind::printable:
    case KeyPattern::Kind::any: return {};
    }
    return {};
}

} // namespace

TEST_CASE("each context reads its keys as the thesis' commands", "[session][keys]")
{
    const std::vector<std::tuple<KeyContext, KeyEvent, std::optional<Command>>> rows{
        // Digits and the arrows on the keypad are equal (SPEC §7.3).
        {KeyContext::control_choice, ch(U'8'), cmd::ChooseGlobal{}},
        {KeyContext::control_choice, key(Key::up), cmd::ChooseGlobal{}},
        {KeyContext::control_choice, ch(U'2'), cmd::ChooseLocal{}},
        {KeyContext::control_choice, key(Key::down), cmd::ChooseLocal{}},
        {KeyContext::control_choice, ch(U'6'), std::nullopt},
        {KeyContext::control_choice, ch(U'k'), cmd::ToggleKeyFrames{}},
        {KeyContext::region_pick, ch(U'4'), cmd::ArrowMove{-1}},
        {KeyContext::region_pick, key(Key::left), cmd::ArrowMove{-1}},
        {KeyContext::region_pick, ch(U'6'), cmd::ArrowMove{+1}},
        {KeyContext::region_pick, key(Key::right), cmd::ArrowMove{+1}},
        {KeyContext::region_pick, key(Key::enter), cmd::Accept{}},
        {KeyContext::region_pick, key(Key::escape), cmd::Back{}},
        {KeyContext::region_pick, ch(U'J'), std::nullopt},
        // The staff: 4/6 one step, Shift-J/L three (j and l too), Enter accepts, Esc keeps.
        {KeyContext::staff, ch(U'4'), cmd::StaffStep{-1}},
        {KeyContext::staff, key(Key::left), cmd::StaffStep{-1}},
        {KeyContext::staff, ch(U'6'), cmd::StaffStep{+1}},
        {KeyContext::staff, key(Key::right), cmd::StaffStep{+1}},
        {KeyContext::staff, ch(U'J'), cmd::StaffStep{-3}},
        {KeyContext::staff, ch(U'j'), cmd::StaffStep{-3}},
        {KeyContext::staff, ch(U'L'), cmd::StaffStep{+3}},
        {KeyContext::staff, ch(U'l'), cmd::StaffStep{+3}},
        {KeyContext::staff, key(Key::enter), cmd::Accept{}},
        {KeyContext::staff, key(Key::escape), cmd::Keep{}},
        {KeyContext::staff, key(Key::up), std::nullopt},
        {KeyContext::staff, ch(U'8'), std::nullopt},
        // Ask_Adjusting: Y again, anything else accepts, K still shows the keys.
        {KeyContext::adjust_again, ch(U'y'), cmd::Yes{}},
        {KeyContext::adjust_again, ch(U'Y'), cmd::Yes{}},
        {KeyContext::adjust_again, ch(U'N'), cmd::No{}},
        {KeyContext::adjust_again, ch(U'n'), cmd::No{}},
        {KeyContext::adjust_again, key(Key::enter), cmd::No{}},
        {KeyContext::adjust_again, ch(U'K'), cmd::ToggleKeyFrames{}},
        // A stray key does not accept the path.
        {KeyContext::adjust_again, ch(U'6'), std::nullopt},
        {KeyContext::adjust_again, key(Key::escape), std::nullopt},
        // Help, pictures and quitting in graphics mode; at a text prompt ? and q are typed.
        {KeyContext::staff, ch(U'?'), cmd::ShowHelp{}},
        {KeyContext::staff, key(Key::f1), cmd::ShowHelp{}},
        {KeyContext::region_pick, ch(U'q'), cmd::Quit{}},
        {KeyContext::control_choice, ch(U'p'), cmd::SavePicture{}},
        {KeyContext::text_line, key(Key::f1), cmd::ShowHelp{}},
        {KeyContext::text_line, ch(U'?'), cmd::TypeCharacter{U'?'}},
        {KeyContext::text_line, ch(U'q'), cmd::TypeCharacter{U'q'}},
        {KeyContext::quit_question, ch(U'y'), cmd::Yes{}},
        {KeyContext::quit_question, key(Key::enter), cmd::No{}},
        {KeyContext::quit_question, key(Key::escape), cmd::No{}},
        {KeyContext::quit_question, ch(U'N'), cmd::No{}},
        {KeyContext::quit_question, ch(U'x'), std::nullopt},
        {KeyContext::help_screen, ch(U'x'), cmd::Continue{}},
        {KeyContext::any_key_graphics, ch(U'P'), cmd::SavePicture{}},
        {KeyContext::any_key_graphics, ch(U'x'), cmd::Continue{}},
        {KeyContext::any_key, ch(U'P'), cmd::Continue{}},
        // Questions of the text console.
        {KeyContext::yes_to_go_on, ch(U'y'), cmd::Yes{}},
        {KeyContext::yes_to_go_on, key(Key::enter), std::nullopt},
        {KeyContext::enter_to_go_on, key(Key::enter), cmd::Continue{}},
        {KeyContext::enter_to_go_on, ch(U'x'), std::nullopt},
        {KeyContext::enter_to_go_on, ch(U'q'), cmd::Quit{}},
        {KeyContext::any_key, key(Key::escape), cmd::Continue{}},
        {KeyContext::any_key, ch(U'x'), cmd::Continue{}},
        {KeyContext::any_key, ch(U'q'), cmd::Quit{}},
        // The animation.
        {KeyContext::animation, key(Key::escape), cmd::StopAnimation{}},
        {KeyContext::animation, key(Key::space), cmd::Pause{}},
        {KeyContext::animation, ch(U'r'), cmd::Replay{}},
        {KeyContext::animation, key(Key::enter), std::nullopt},
        {KeyContext::finished, key(Key::enter), std::nullopt},
    };
    for (const auto& [context, event, expected] : rows) {
        CAPTURE(static_cast<int>(context), static_cast<int>(event.key), static_cast<std::uint32_t>(event.character));
        REQUIRE(command_for(context, event) == expected);
    }
}

TEST_CASE("at a text prompt every printable key is typed text, digits and letters alike", "[session][keys]")
{
    for (const char32_t typed : {U'4', U'6', U'8', U'2', U'J', U'L', U'K', U'Y', U'q', U'-', U'.', U'é', U'?'})
        REQUIRE(command_for(KeyContext::text_line, ch(typed)) == Command{cmd::TypeCharacter{typed}});
    REQUIRE(command_for(KeyContext::text_line, key(Key::space)) == Command{cmd::TypeCharacter{U' '}});
    REQUIRE(command_for(KeyContext::text_line, key(Key::enter)) == Command{cmd::SubmitLine{}});
    REQUIRE(command_for(KeyContext::text_line, key(Key::backspace)) == Command{cmd::EraseCharacter{}});
    REQUIRE(command_for(KeyContext::text_line, key(Key::escape)) == Command{cmd::ClearLine{}});
    REQUIRE(command_for(KeyContext::text_line, key(Key::left)) == std::nullopt);
    REQUIRE(command_for(KeyContext::text_line, ch(U'\x07')) == std::nullopt);
}

TEST_CASE("the key line of graphics mode is made from the key map's rows", "[session][keys]")
{
    REQUIRE(key_help(KeyContext::staff) == "4/6 J/L step  = type  Enter accept  Esc keep  U undo  K/T/G/O/Z/C view  ? help");
    REQUIRE(key_help(KeyContext::control_choice) == "W waypoints  U undo  K/T/G/O/Z/C view  ? help  q quit");
    REQUIRE(key_help(KeyContext::region_pick) == "K/T/G/O/Z/C view  ? help  q quit");
    REQUIRE(key_help(KeyContext::adjust_again) == "U undo  K/T/G/O/Z/C view  ? help  q quit");
    REQUIRE(key_help(KeyContext::waypoints) ==
            "Tab point  2468 +- move  I/D ins/del  U undo  Enter keep  Esc drop  ? help");
    REQUIRE(key_help(KeyContext::value_field) == "Enter set  Backspace erase  Esc close");
    REQUIRE(key_help(KeyContext::animation) == "Esc stop  Space pause  R replay  ,. frame  ? help  q quit");
    // Every key line fits the 80 columns of the screen, after its first.
    for (const KeyContext context : all_contexts)
        REQUIRE(key_help(context).size() <= 78);
    REQUIRE(key_help(KeyContext::text_line).empty());
}

TEST_CASE("the help screen lists every key of a step with what it means, keys of one meaning together",
          "[session][keys]")
{
    const std::vector<std::string> staff = key_help_lines(KeyContext::staff);
    REQUIRE(staff.front() == "  4, Left, 6, Right  the value one step left, right");
    REQUIRE(std::find(staff.begin(), staff.end(), "  J, L            three steps left, right (Shift-J, Shift-L)") !=
            staff.end());
    REQUIRE(std::find(staff.begin(), staff.end(), "  ?, F1           this help") != staff.end());
    REQUIRE(std::find(staff.begin(), staff.end(), "  q               end APCS without saving this path (asks first)") !=
            staff.end());
    // Every context a step listens in has a help screen that names at least one key.
    for (const KeyContext context : {KeyContext::text_line, KeyContext::yes_to_go_on, KeyContext::enter_to_go_on,
                                     KeyContext::any_key, KeyContext::any_key_graphics, KeyContext::control_choice,
                                     KeyContext::region_pick, KeyContext::staff, KeyContext::adjust_again,
                                     KeyContext::animation, KeyContext::quit_question, KeyContext::value_field,
                                     KeyContext::waypoints})
        REQUIRE_FALSE(key_help_lines(context).empty());
}

TEST_CASE("every help screen fits the 80x24 console: lines of at most 79 columns and every key line shown",
          "[session][keys]")
{
    for (const KeyContext context : all_contexts) {
        const std::vector<std::string> lines = key_help_lines(context);
        for (const std::string& line : lines)
            REQUIRE(line.size() <= 79);
        // Over the path screen the colour legend shares the screen: no key line may give way to it.
        const CellGrid screen = key_help_screen("a step", context, "");
        std::vector<std::string> shown;
        for (int row = 0; row < screen.rows(); ++row)
            shown.push_back(screen.row_text(row));
        for (const std::string& line : lines) {
            CAPTURE(static_cast<int>(context), line);
            REQUIRE(std::find_if(shown.begin(), shown.end(), [&](const std::string& row) {
                        return row.rfind(line, 0) == 0 && row.find_first_not_of(' ', line.size()) == std::string::npos;
                    }) != shown.end());
        }
    }
    const std::vector<std::string> waypoints = key_help_lines(KeyContext::waypoints);
    REQUIRE(std::find(waypoints.begin(), waypoints.end(), "  4, Left, 6, Right  move the point one step left, right") !=
            waypoints.end());
    // The whole screen too, its footer included: nothing reaches the 80th column, where it is cut.
    const CellGrid screen = key_help_screen("step 1: KEY1 file", KeyContext::text_line, "key1.dat");
    for (int row = 0; row < screen.rows(); ++row) {
        CAPTURE(screen.row_text(row));
        REQUIRE(screen.row_text(row).substr(79).find_first_not_of(' ') == std::string::npos);
    }
}

TEST_CASE("a letter is spelt alike on the key line and on the help screen: q quit, never Q", "[session][keys]")
{
    for (const KeyBinding& binding : key_bindings()) {
        if (binding.pattern.kind != KeyPattern::Kind::letter || binding.key_line_words.empty())
            continue;
        CAPTURE(binding.key_line_words);
        // The key line names a letter first ("q quit", "K/T/G show"), the help screen by key_label.
        REQUIRE(binding.key_line_words.find(key_label(binding.pattern)) != std::string_view::npos);
    }
    const std::vector<std::string> animation = key_help_lines(KeyContext::animation);
    REQUIRE(std::find(animation.begin(), animation.end(), "  q               end APCS; every file written so far stays") !=
            animation.end());
}

TEST_CASE("a text prompt's help names the answer an empty line takes there — a long one goes on below", "[session][keys]")
{
    const std::vector<std::string> key1 = key_help_lines(KeyContext::text_line, "key1.dat");
    REQUIRE(key1.front() == "  Enter           answer; an empty line takes key1.dat");
    REQUIRE(key1[2] == "  Esc             clear the line; on an empty line, ask \"Quit APCS ? (Y/N)\"");
    REQUIRE(key_help_lines(KeyContext::text_line).front() ==
            "  Enter           answer; an empty line takes the prompt's example answer");
    const std::vector<std::string> slopes =
        key_help_lines(KeyContext::text_line, "0.30000000000000004 0.30000000000000004");
    REQUIRE(slopes[0] == "  Enter           answer; an empty line takes 0.30000000000000004");
    REQUIRE(slopes[1] == "                  0.30000000000000004");
    REQUIRE(slopes[2].starts_with("  Backspace"));
    const std::vector<std::string> unbroken = key_help_lines(KeyContext::text_line, std::string(100, '7'));
    REQUIRE(unbroken[0] == "  Enter           answer; an empty line takes");
    REQUIRE(unbroken[1] == "                  " + std::string(61, '7'));
    REQUIRE(unbroken[2] == "                  " + std::string(39, '7'));
}

TEST_CASE("no key map row is hidden behind an earlier row of its context", "[session][keys]")
{
    const auto bindings = key_bindings();
    for (std::size_t later = 0; later < bindings.size(); ++later)
        for (const KeyContext context : all_contexts) {
            if (!bindings[later].contexts.contains(context))
                continue;
            for (const KeyEvent& example : examples_of(bindings[later].pattern)) {
                CAPTURE(later, static_cast<int>(context), static_cast<int>(example.key));
                REQUIRE(command_for(context, example) == bindings[later].command);
            }
        }
}

TEST_CASE("a keypad pattern means the arrow and the digit on the same key, and the help screen names both",
          "[session][keys]")
{
    const std::tuple<Key, char32_t, std::string> rows[] = {
        {Key::left, U'4', "4, Left"}, {Key::right, U'6', "6, Right"}, {Key::up, U'8', "8, Up"}, {Key::down, U'2', "2, Down"}};
    for (const auto& [arrow, digit, label] : rows) {
        const KeyPattern pattern = KeyPattern::keypad(arrow);
        REQUIRE(pattern.matches(key(arrow)));
        REQUIRE(pattern.matches(ch(digit)));
        REQUIRE_FALSE(pattern.matches(ch(U'5')));
        REQUIRE_FALSE(pattern.matches(key(Key::enter)));
        REQUIRE(key_label(pattern) == label);
    }
}

TEST_CASE("a key context set holds the contexts it was given and no other", "[session][keys]")
{
    const KeyContexts staff_and_waypoints{KeyContext::staff, KeyContext::waypoints};
    for (const KeyContext context : all_contexts)
        REQUIRE(staff_and_waypoints.contains(context) ==
                (context == KeyContext::staff || context == KeyContext::waypoints));
    REQUIRE(KeyContexts{KeyContext::finished}.contains(KeyContext::finished));
    REQUIRE_FALSE(KeyContexts{}.contains(KeyContext::text_line));
}

TEST_CASE("every physical key's row gives its script token, read back as the key, and its help label",
          "[session][keys]")
{
    for (const PhysicalKey& row : physical_keys) {
        CAPTURE(std::string(row.script_name));
        const Expected<std::vector<KeyEvent>> parsed = parse_key_script(row.script_name, "keys.txt");
        REQUIRE(parsed);
        REQUIRE(*parsed == std::vector<KeyEvent>{key(row.key)});
        REQUIRE(format_key_script({key(row.key)}) == std::string(row.script_name) + "\n");
        REQUIRE(key_label(KeyPattern::of(row.key)) == row.help_label);
    }
    REQUIRE(find_physical_key(Key::character) == nullptr);
}

TEST_CASE("a script token that names no key is refused with the list of every key's token", "[session][keys]")
{
    const Expected<std::vector<KeyEvent>> parsed = parse_key_script("ENTER\nF2\n", "keys.txt");
    REQUIRE_FALSE(parsed);
    REQUIRE(parsed.error().line == 2);
    REQUIRE(parsed.error().message == "expected a single printable character or ENTER, ESC, SPACE, LEFT, RIGHT, UP, "
                                      "DOWN, BACKSPACE, TAB, BTAB, F1, CTRL-L, PGDN, PGUP, HOME; found 'F2'");
}

TEST_CASE("a key script's lines may end with LF, CR LF or CR alone, as a .dat file's", "[session][keys]")
{
    const std::vector<KeyEvent> expected{KeyEvent::typed('Y'), KeyEvent::of(Key::enter), KeyEvent::typed('8'),
                                         KeyEvent::of(Key::escape)};
    for (const char* text : {"Y\nENTER\n8\nESC\n", "Y\r\nENTER\r\n8\r\nESC\r\n", "Y\rENTER\r8\rESC\r", "Y\rENTER\r\n8\nESC"}) {
        const Expected<std::vector<KeyEvent>> parsed = parse_key_script(text, "keys.txt");
        REQUIRE(parsed);
        REQUIRE(*parsed == expected);
    }
    // TEXT types the rest of its line only: a CR ends it.
    const Expected<std::vector<KeyEvent>> typed = parse_key_script("TEXT ab\rENTER\r", "keys.txt");
    REQUIRE(typed);
    REQUIRE(*typed == std::vector<KeyEvent>{KeyEvent::typed('a'), KeyEvent::typed('b'), KeyEvent::of(Key::enter)});
}

TEST_CASE("a DOS editor's Ctrl-Z ends a key script — more keys after it are refused at its line", "[session][keys]")
{
    const Expected<std::vector<KeyEvent>> ended = parse_key_script("Y\r\nENTER\r\n\x1A\r\n", "keys.txt");
    REQUIRE(ended);
    REQUIRE(*ended == std::vector<KeyEvent>{KeyEvent::typed('Y'), KeyEvent::of(Key::enter)});
    const Expected<std::vector<KeyEvent>> last_line = parse_key_script("Y\nENTER\x1A", "keys.txt");
    REQUIRE(last_line);
    REQUIRE(last_line->size() == 2);

    const Expected<std::vector<KeyEvent>> more = parse_key_script("Y\r\nENTER\x1A\r\nN\r\n", "keys.txt");
    REQUIRE_FALSE(more);
    REQUIRE(more.error().to_string() ==
            "keys.txt:2: Ctrl-Z (end of file) followed by more data; expected it only at the end");
}
