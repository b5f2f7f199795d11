// SPEC §3.2: PgDn K shows caption K beside the screen its keys made, which is what the handout's
// page K shows: at 80x24 every row below the badge's is the same.
#include "apcs/lesson/handout.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/raster/replay_caption.h"

#include "support/replay_deck.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

using namespace apcs;
namespace fs = std::filesystem;

namespace {

// The rows of a screen's text after the first (the badge's row on a terminal).
std::string below_badge_row(const std::string& text) { return text.substr(text.find('\n') + 1); }

} // namespace

TEST_CASE("each PgDn of a lesson shows at 80x24 what the handout's page for that caption shows, every row below "
          "the badge's",
          "[lesson][replay][deck][handout]")
{
    const std::string name = GENERATE(as<std::string>{}, "lesson.keys", "lesson-waypoints.keys",
                                      "lesson-continuity.keys", "lesson-bias.keys", "lesson-regions.keys",
                                      "lesson-acceleration.keys", "lesson-surface.keys");
    CAPTURE(name);
    const fs::path lessons = test::data_folder / "n-to-l";
    const test::TempFolder work;
    for (const auto& entry : fs::directory_iterator(lessons))
        fs::copy_file(entry.path(), work / entry.path().filename().string());
    const test::TempFolder handout;
    fs::remove(handout.path());
    const auto made = test::run_apcs({"--keys", (work / name).string(), "--workdir", work.path().string(), "--handout",
                                      handout.path().string(), "--glyphs", "ascii"});
    INFO(made.err);
    REQUIRE(made.status == 0);

    const KeyScript script = test::read_script(lessons / name);
    test::Deck deck(script, "n-to-l");
    std::size_t pages = 0;
    for (std::size_t caption = 0; caption < script.captions.size(); ++caption) {
        deck.press(KeyEvent::of(Key::page_down));
        const SessionScreen shown = deck.replay->screen();
        INFO("caption " << caption + 1 << ": " << script.captions[caption].text);
        REQUIRE(shown.caption == script.captions[caption].text);
        const fs::path page = handout / (handout_file_stem(static_cast<int>(caption) + 1, script.captions.size(),
                                                           script.captions[caption].text) +
                                         ".txt");
        if (!fs::exists(page)) // an empty prompt has no page (handout.h)
            continue;
        ++pages;
        REQUIRE(below_badge_row(screen_text(with_caption(shown, shown.caption), GlyphSet::ascii)) ==
                below_badge_row(test::read_all(page)));
    }
    REQUIRE(pages + 1 >= script.captions.size());
}
