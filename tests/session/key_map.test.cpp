#include "apcs/session/key_map.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <tuple>
#include <vector>

using namespace apcs;
namespace cmd = apcs::command;

namespace {

KeyEvent ch(char32_t c) { return KeyEvent::typed(c); }
KeyEvent key(Key k) { return KeyEvent::of(k); }

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
    REQUIRE(key_help(KeyContext::staff) == "4/6 J/L step  = type  Enter accept  Esc keep  U undo  K/T/G show  ? help");
    REQUIRE(key_help(KeyContext::control_choice) == "W waypoints  U undo  K/T/G show  ? help  q quit");
    REQUIRE(key_help(KeyContext::region_pick) == "K/T/G show  ? help  q quit");
    REQUIRE(key_help(KeyContext::adjust_again) == "U undo  K/T/G show  ? help  q quit");
    REQUIRE(key_help(KeyContext::waypoints) ==
            "Tab point  2468 +- move  I/D ins/del  U undo  Enter keep  Esc drop  ? help");
    REQUIRE(key_help(KeyContext::value_field) == "Enter set  Backspace erase  Esc close");
    REQUIRE(key_help(KeyContext::animation) == "Esc stop  Space pause  R replay  ? help  q quit");
    // Every key line fits the 80 columns of the screen, after its first.
    for (const KeyBinding& binding : key_bindings())
        REQUIRE(key_help(binding.context).size() <= 78);
    REQUIRE(key_help(KeyContext::text_line).empty());
}

TEST_CASE("the help screen lists every key of a step with what it means, keys of one meaning together",
          "[session][keys]")
{
    const std::vector<std::string> staff = key_help_lines(KeyContext::staff);
    REQUIRE(staff.front() == "  4, Left         the value one step left");
    REQUIRE(std::find(staff.begin(), staff.end(), "  J               three steps left (Shift-J)") != staff.end());
    REQUIRE(std::find(staff.begin(), staff.end(), "  ?, F1           this help") != staff.end());
    REQUIRE(std::find(staff.begin(), staff.end(), "  Q               end APCS without saving this path (asks first)") !=
            staff.end());
    // Every context a step listens in has a help screen that names at least one key.
    for (const KeyContext context : {KeyContext::text_line, KeyContext::yes_to_go_on, KeyContext::enter_to_go_on,
                                     KeyContext::any_key, KeyContext::any_key_graphics, KeyContext::control_choice,
                                     KeyContext::region_pick, KeyContext::staff, KeyContext::adjust_again,
                                     KeyContext::animation, KeyContext::quit_question, KeyContext::value_field,
                                     KeyContext::waypoints})
        REQUIRE_FALSE(key_help_lines(context).empty());
}

TEST_CASE("every help screen fits the 80x24 console: lines of at most 79 columns, rows 2 to 20", "[session][keys]")
{
    for (const KeyBinding& binding : key_bindings()) {
        const std::vector<std::string> lines = key_help_lines(binding.context);
        REQUIRE(lines.size() <= 19);
        for (const std::string& line : lines)
            REQUIRE(line.size() <= 79);
    }
    const std::vector<std::string> waypoints = key_help_lines(KeyContext::waypoints);
    REQUIRE(std::find(waypoints.begin(), waypoints.end(), "  4, Left, 6, Right  move the point one step left, right") !=
            waypoints.end());
}

TEST_CASE("no key map row is hidden behind an earlier row of its context", "[session][keys]")
{
    const auto bindings = key_bindings();
    for (std::size_t later = 0; later < bindings.size(); ++later) {
        const KeyPattern& pattern = bindings[later].pattern;
        if (pattern.kind == KeyPattern::Kind::any || pattern.kind == KeyPattern::Kind::printable)
            continue;
        const KeyEvent example = pattern.kind == KeyPattern::Kind::key ? KeyEvent::of(pattern.key)
                                                                        : KeyEvent::typed(pattern.character);
        CAPTURE(later);
        REQUIRE(command_for(bindings[later].context, example) == bindings[later].command);
    }
}
