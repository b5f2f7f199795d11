// SPEC §3.1, §3.2: what a caption says can be seen from the back row. A caption of a shipped script
// that names a visible change, and has keys before the next caption, names what changes, and at
// least 12 cells of that thing's colour role change between the screen before its keys and the
// screen after them, on the 80x23 pane a class shares (tmux under its status line), in every
// glyph set.
#include "apcs/cli/session_command.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/short_screen.h"
#include "apcs/session/session_files.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using namespace apcs;

namespace {

const std::filesystem::path data_folder = std::filesystem::path(APCS_SOURCE_DIR) / "data";

// The fewest cells a named change must change (SPEC §3.1).
constexpr int fewest_changed_cells = 12;

bool names_a_visible_change(const std::string& caption)
{
    static const std::regex visible_change(
        R"(\b(shows|corner|loop|crowd|tighten|shorten|turn|bend|overshoot|spike|straighten|halve|lean|swing|boxed)\w*)",
        std::regex::icase);
    return std::regex_search(caption, visible_change);
}

// The things a caption can name, each drawn in a colour role of its own (SPEC §7.2.1).
struct NamedThing {
    std::regex words;
    ColourRole role;
};

const std::vector<NamedThing>& named_things()
{
    static const std::vector<NamedThing> things{
        {std::regex(R"(\b(tangents?|arrows?|DS|DD)\b)"), ColourRole::tangent},
        {std::regex(R"(\b(curve|corner|spike)\b)"), ColourRole::monitor},
        {std::regex(R"(\b(marks|in-betweens|frames)\b)"), ColourRole::inbetween},
        {std::regex(R"(\blaw\b)"), ColourRole::law},
        {std::regex(R"(\bregion\b)"), ColourRole::region},
        {std::regex(R"(\bghost\b)"), ColourRole::ghost},
        {std::regex(R"(\breference\b)"), ColourRole::reference},
    };
    return things;
}

// The colour roles of the things `caption` names.
std::vector<ColourRole> named_roles(const std::string& caption)
{
    std::vector<ColourRole> roles;
    for (const NamedThing& thing : named_things())
        if (std::regex_search(caption, thing.words))
            roles.push_back(thing.role);
    return roles;
}

// Whether caption `k` is an exercise's task: it says what the student is to reach, and the keys
// after it are an answer's or the student's, not a demonstration of what it says.
bool is_task(const KeyScript& script, std::size_t k)
{
    return std::any_of(script.goals.begin(), script.goals.end(),
                       [k](const ScriptGoal& goal) { return goal.captions_before == k + 1; });
}

// Every key script under data/ that holds a caption, as paths relative to data/.
std::vector<std::filesystem::path> captioned_scripts()
{
    std::vector<std::filesystem::path> scripts;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(data_folder)) {
        if (entry.path().extension() != ".keys")
            continue;
        const Expected<KeyScript> script = parse_captioned_key_script(test::read_all(entry.path()), entry.path().string());
        // A script refused (a caption too wide) would drop out of the test unseen.
        CAPTURE(entry.path().string());
        REQUIRE(script);
        if (!script->captions.empty())
            scripts.push_back(std::filesystem::relative(entry.path(), data_folder));
    }
    std::sort(scripts.begin(), scripts.end());
    return scripts;
}

// The screens of a headless replay of `script` in a fresh copy of its folder: the one each caption
// is told over, then the last.
std::vector<ProgramScreen> caption_screens(const std::filesystem::path& script_file, const KeyScript& script,
                                           GlyphSet glyphs)
{
    const test::TempFolder folder;
    // An answer's inputs are its exercise's, in the folder above answers/.
    std::filesystem::path inputs = data_folder / script_file.parent_path();
    if (inputs.filename() == "answers")
        inputs = inputs.parent_path();
    for (const auto& entry : std::filesystem::directory_iterator(inputs))
        if (entry.is_regular_file())
            std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
    FolderFiles files(folder.path());
    Session session({}, files);
    std::vector<ProgramScreen> screens;
    ReplayHooks hooks;
    hooks.caption_reached = [&](std::size_t, const ProgramScreen& shown) { screens.push_back(shown); };
    ReplayDriver replay(session, script, script_file.string(), ReplayPace{}, hooks, ReplayAudience::headless);
    std::ostream no_screens(nullptr);
    run_headless_session(replay, session, glyphs, no_screens);
    screens.push_back(session.screen());
    return screens;
}

// The screen on an 80x23 pane, as the terminal lays it (run_terminal_program.cpp).
CellGrid cells_of(const ProgramScreen& screen, GlyphSet glyphs)
{
    return screen.graphics ? render_screen_cells(screen.picture, {80, short_screen_rows}, glyphs)
                           : text_on_short_screen(screen.text);
}

bool is_blank(char32_t glyph) { return glyph == U' ' || glyph == U'\u2800'; }

// The cells of the short screen's drawing area (the rows above its message line) that show `role`
// before or after and differ in character or role; a cell another thing the caption names shows
// before or after is not counted (hiding the tangents uncovers the curve under them: that is no
// change of the curve).
int changed_cells_of(ColourRole role, const std::vector<ColourRole>& named, const ProgramScreen& before,
                     const ProgramScreen& after, GlyphSet glyphs)
{
    const CellGrid a = cells_of(before, glyphs);
    const CellGrid b = cells_of(after, glyphs);
    const auto shows = [](ColourRole shown, const CellGrid& grid, int column, int row) {
        return grid.role_at(column, row) == shown && !is_blank(grid.at(column, row));
    };
    const auto other_named = [&](int column, int row) {
        return std::any_of(named.begin(), named.end(), [&](ColourRole other) {
            return other != role && (shows(other, a, column, row) || shows(other, b, column, row));
        });
    };
    int changed = 0;
    for (int row = 0; row < layout::message_row - 1; ++row)
        for (int column = 0; column < 80; ++column)
            changed += (shows(role, a, column, row) || shows(role, b, column, row)) && !other_named(column, row) &&
                               (a.at(column, row) != b.at(column, row) || a.role_at(column, row) != b.role_at(column, row))
                           ? 1
                           : 0;
    return changed;
}

} // namespace

TEST_CASE("a caption that names a visible change names what changes, and at least 12 cells of its colour role "
          "change on an 80x23 pane in every glyph set",
          "[lesson][captions][visible]")
{
    const std::vector<std::filesystem::path> scripts = captioned_scripts();
    REQUIRE(scripts.size() >= 15);
    int checked = 0;
    for (const std::filesystem::path& script_file : scripts) {
        const Expected<KeyScript> script = parse_captioned_key_script(test::read_all(data_folder / script_file),
                                                                      (data_folder / script_file).string());
        REQUIRE(script);
        for (const GlyphSet glyphs : {GlyphSet::braille, GlyphSet::ascii, GlyphSet::blocks}) {
            const std::vector<ProgramScreen> screens = caption_screens(script_file, *script, glyphs);
            REQUIRE(screens.size() == script->captions.size() + 1);
            for (std::size_t k = 0; k < script->captions.size(); ++k) {
                const ScriptCaption& caption = script->captions[k];
                const std::size_t keys_end =
                    k + 1 < script->captions.size() ? script->captions[k + 1].before_event : script->events.size();
                if (!names_a_visible_change(caption.text) || keys_end == caption.before_event || is_task(*script, k))
                    continue;
                CAPTURE(script_file.string(), caption.text, static_cast<int>(glyphs));
                const std::vector<ColourRole> roles = named_roles(caption.text);
                CHECK_FALSE(roles.empty());
                for (const ColourRole role : roles) {
                    CAPTURE(colour_role_name(role));
                    CHECK(changed_cells_of(role, roles, screens[k], screens[k + 1], glyphs) >= fewest_changed_cells);
                    ++checked;
                }
            }
        }
    }
    // The lessons' and the sessions' named changes (an exercise's task is the student's to make).
    REQUIRE(checked >= 3 * 15);
}
