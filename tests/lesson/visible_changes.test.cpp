// SPEC §3.1: what a caption says can be seen. A caption of a shipped script that names a visible
// change, and has keys before the next caption, changes at least 12 cells of the drawing area at
// 80x24 between the screen before its keys and the screen after them, in every glyph set.
#include "apcs/cli/session_command.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/raster/screen_layout.h"
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
    static const std::regex visible_change(R"(\b(corner|loop|crowd|tighten|shorten|turn|bend|overshoot|spike|straighten)\w*)",
                                           std::regex::icase);
    return std::regex_search(caption, visible_change);
}

// Every key script under data/ that holds a caption, as paths relative to data/.
std::vector<std::filesystem::path> captioned_scripts()
{
    std::vector<std::filesystem::path> scripts;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(data_folder)) {
        if (entry.path().extension() != ".keys")
            continue;
        const Expected<KeyScript> script = parse_captioned_key_script(test::read_all(entry.path()), entry.path().string());
        if (script && !script->captions.empty())
            scripts.push_back(std::filesystem::relative(entry.path(), data_folder));
    }
    std::sort(scripts.begin(), scripts.end());
    return scripts;
}

// The screens of a headless replay of `script` in a fresh copy of its folder: the one each caption
// is told over, then the last.
std::vector<SessionScreen> caption_screens(const std::filesystem::path& script_file, const KeyScript& script,
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
    std::vector<SessionScreen> screens;
    ReplayHooks hooks;
    hooks.caption_reached = [&](std::size_t, const SessionScreen& shown) { screens.push_back(shown); };
    ReplayDriver replay(session, script, script_file.string(), ReplayPace{}, hooks, ReplayAudience::headless);
    std::ostream no_screens(nullptr);
    run_headless_session(replay, session, glyphs, no_screens);
    screens.push_back(session.screen());
    return screens;
}

CellGrid cells_of(const SessionScreen& screen, GlyphSet glyphs)
{
    return screen.graphics ? render_cells(screen.picture, {80, 24}, glyphs) : screen.text;
}

// The cells of the drawing area (the rows above the message line) that differ.
int changed_drawing_cells(const SessionScreen& before, const SessionScreen& after, GlyphSet glyphs)
{
    const CellGrid a = cells_of(before, glyphs);
    const CellGrid b = cells_of(after, glyphs);
    int changed = 0;
    for (int row = 0; row < layout::message_row; ++row)
        for (int column = 0; column < 80; ++column)
            changed += a.at(column, row) != b.at(column, row) ? 1 : 0;
    return changed;
}

} // namespace

TEST_CASE("a caption that names a visible change changes at least 12 cells of the drawing area in every glyph set",
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
            const std::vector<SessionScreen> screens = caption_screens(script_file, *script, glyphs);
            REQUIRE(screens.size() == script->captions.size() + 1);
            for (std::size_t k = 0; k < script->captions.size(); ++k) {
                const ScriptCaption& caption = script->captions[k];
                const std::size_t keys_end =
                    k + 1 < script->captions.size() ? script->captions[k + 1].before_event : script->events.size();
                if (!names_a_visible_change(caption.text) || keys_end == caption.before_event)
                    continue;
                CAPTURE(script_file.string(), caption.text, static_cast<int>(glyphs));
                CHECK(changed_drawing_cells(screens[k], screens[k + 1], glyphs) >= fewest_changed_cells);
                ++checked;
            }
        }
    }
    // The lessons on continuity, bias, acceleration and regions, the exercises' answers, the sessions.
    REQUIRE(checked >= 3 * 15);
}
