// When a caption ends (ReplayHooks::caption_ended, the moment --handout writes its page): once its
// keys have played, so that the page shows what the caption says (issue 42 item 6).
#include "apcs/lesson/handout.h"
#include "apcs/input/play_to_idle.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/session/session_files.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace apcs;

namespace {

const std::filesystem::path n_to_l = std::filesystem::path(APCS_SOURCE_DIR) / "data" / "n-to-l";

MemoryFiles n_to_l_files()
{
    MemoryFiles files;
    for (const auto& entry : std::filesystem::directory_iterator(n_to_l))
        if (entry.path().extension() == ".dat")
            files.files[entry.path().filename().string()] = test::read_all(entry.path());
    return files;
}

KeyScript script_of(const std::string& text)
{
    Expected<KeyScript> script = parse_captioned_key_script(text, "test.keys");
    REQUIRE(script);
    return std::move(*script);
}

// What the hooks were told, in order: "reached 0", "ended 0" …, and each caption's screens (as
// ascii text, no caption laid on) where it was reached and where it ended.
struct CaptionLog {
    std::vector<std::string> events;
    std::vector<std::string> reached;
    std::vector<std::string> ended;
    std::vector<std::string> ended_captions; // as shown: "(not reached) ..." after a goal not reached
};

ReplayHooks logging_hooks(CaptionLog& log, const Session& session)
{
    ReplayHooks hooks;
    hooks.caption_reached = [&log, &session](std::size_t index, const ProgramScreen&) {
        log.events.push_back("reached " + std::to_string(index));
        log.reached.push_back(screen_text(session.screen(), GlyphSet::ascii));
    };
    hooks.caption_ended = [&log](std::size_t index, const std::string& caption, const ProgramScreen& screen,
                                const std::vector<std::string>&) {
        log.events.push_back("ended " + std::to_string(index));
        log.ended_captions.push_back(caption);
        log.ended.push_back(screen_text(screen, GlyphSet::ascii));
    };
    return hooks;
}

CaptionLog headless_captions(const KeyScript& script)
{
    MemoryFiles files = n_to_l_files();
    Session session({}, files);
    CaptionLog log;
    ReplayDriver replay(session, script, "test.keys", ReplayPace{}, logging_hooks(log, session), ReplayAudience::headless);
    play_to_idle(replay);
    replay.finish();
    return log;
}

// "reached 0", "ended 0", "reached 1", … for `count` captions.
std::vector<std::string> each_reached_then_ended(std::size_t count)
{
    std::vector<std::string> events;
    for (std::size_t index = 0; index < count; ++index) {
        events.push_back("reached " + std::to_string(index));
        events.push_back("ended " + std::to_string(index));
    }
    return events;
}

} // namespace

TEST_CASE("a caption ends once its keys have played: T's page has the tangents' numbers, its first screen not",
          "[lesson][handout]")
{
    const KeyScript script = script_of(test::read_all(n_to_l / "lesson.keys"));
    const CaptionLog log = headless_captions(script);
    REQUIRE(log.events == each_reached_then_ended(script.captions.size()));
    // Caption 2, "T shows the tangents", plays T 8: the message line then names DS and DD.
    REQUIRE(script.captions[1].text.starts_with("T shows the tangents"));
    REQUIRE(log.reached[1].find("DS 0.00") == std::string::npos);
    REQUIRE(log.ended[1].find(" point 2  DS 0.00 0.00 5.00  DD 0.00 0.00 5.00\n") != std::string::npos);
    // The opening answers play before START: caption 1 is reached over the path screen already.
    REQUIRE(script.preamble_end > 0);
    REQUIRE(log.reached[0].starts_with("+-----"));
    REQUIRE(log.ended[0].starts_with("+-----"));
    // A caption ends where the next is reached; the last, N, once N has played.
    for (std::size_t index = 0; index + 1 < script.captions.size(); ++index) {
        INFO("caption " << index + 1 << ": " << script.captions[index].text);
        REQUIRE(log.ended[index] == log.reached[index + 1]);
        REQUIRE(log.ended[index] != log.reached[index]);
    }
    REQUIRE(log.ended.back() != log.reached.back());
}

TEST_CASE("captions with no keys between them end at once on the screen they are reached over", "[lesson][handout]")
{
    const KeyScript script = script_of(";; a title\n;; the key frames\nENTER ENTER\n;; a summary\n");
    const CaptionLog log = headless_captions(script);
    REQUIRE(log.events == each_reached_then_ended(3));
    REQUIRE(log.ended[0] == log.reached[0]);
    REQUIRE(log.ended[0].starts_with("Please keyin the KEY1 filename!\n_\n"));
    REQUIRE(log.ended[1] != log.reached[1]);
    REQUIRE(log.ended[2] == log.reached[2]);
}

TEST_CASE("headless, each task's page shows its goal's feedback and the caption closing a goal not reached says "
          "so, two goals with no answer between them too",
          "[lesson][handout][goal]")
{
    const KeyScript script = script_of("ENTER ENTER\nTEXT 0 90 100\nENTER\nTEXT way1.dat\nENTER ENTER\nSTART\n"
                                       ";; the staff\n8\n"
                                       ";; Task A\nGOAL VALUE TENSION 0.40 0.60\n"
                                       ";; Task B\nGOAL VALUE BIAS 0.30 0.50\n"
                                       ";; Both done\n");
    const CaptionLog log = headless_captions(script);
    REQUIRE(log.events == each_reached_then_ended(4));
    CHECK(log.ended[0].find("GOAL") == std::string::npos);
    CHECK(log.ended[1].find("\n GOAL: tension +0.00, want +0.40 to +0.60\n") != std::string::npos);
    // On TENSION, a BIAS goal says where the line is (the terminal waiting there says the same).
    CHECK(log.ended[2].find("\n GOAL: you are on TENSION; the goal is BIAS: Enter or Esc goes down a line\n") !=
          std::string::npos);
    CHECK(log.ended[3].find("\n GOAL not reached: bias +0.00, want +0.30 to +0.50\n") != std::string::npos);
    REQUIRE(log.ended_captions.size() == 4);
    CHECK(log.ended_captions[0] == "the staff");
    CHECK(log.ended_captions[1] == "Task A");
    CHECK(log.ended_captions[2] == "Task B");
    CHECK(log.ended_captions[3].starts_with(not_reached_caption_prefix));
    CHECK(log.ended_captions[3].ends_with("Both done"));
    CHECK(log.ended_captions[3].size() == not_reached_caption_prefix.size() + 9);
}

TEST_CASE("a script without captions ends none", "[lesson][handout]")
{
    const CaptionLog log = headless_captions(script_of("ENTER ENTER\n"));
    REQUIRE(log.events.empty());
}

TEST_CASE("paced on a terminal a caption ends once its keys have played, and Esc ends the caption on the row",
          "[lesson][handout]")
{
    const KeyScript script = script_of(test::read_all(n_to_l / "lesson.keys"));
    const CaptionLog headless = headless_captions(script);
    MemoryFiles files = n_to_l_files();
    Session session({}, files);
    CaptionLog log;
    ReplayDriver replay(session, script, "lesson.keys", {ReplayPace::Kind::on_space, 0}, logging_hooks(log, session),
                        ReplayAudience::terminal);
    const auto settle = [&] {
        while (replay.busy())
            replay.work();
    };
    // Space by Space up to the fourth caption's first key (T): three captions ended, as headless.
    while (log.reached.size() < 4 || replay.handled().size() < script.captions[3].before_event) {
        REQUIRE(replay.playing());
        replay.handle(KeyEvent::of(Key::space));
        settle();
    }
    REQUIRE(log.events == std::vector<std::string>{"reached 0", "ended 0", "reached 1", "ended 1", "reached 2",
                                                   "ended 2", "reached 3"});
    for (std::size_t index = 0; index < 3; ++index)
        REQUIRE(log.ended[index] == headless.ended[index]);
    // Space plays T, then Esc: the fourth caption ends on the screen of that moment; no caption follows.
    replay.handle(KeyEvent::of(Key::space));
    settle();
    replay.handle(KeyEvent::of(Key::escape));
    settle();
    REQUIRE(log.events.back() == "ended 3");
    REQUIRE(log.ended.size() == 4);
    REQUIRE(log.ended[3] == screen_text(session.screen(), GlyphSet::ascii));
}
