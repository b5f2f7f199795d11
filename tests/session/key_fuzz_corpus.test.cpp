#include "fuzz/session_keystrokes.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

using namespace apcs;

namespace {

// The corpus' key streams, each its file's name and its bytes.
std::vector<std::pair<std::string, std::string>> corpus_streams()
{
    std::vector<std::pair<std::string, std::string>> streams;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "tests/fuzz/session"))
        streams.emplace_back(entry.path().filename().string(), test::read_all(entry.path()));
    return streams;
}

// Every key of every stream of the corpus, each stream played into a session of its own (few samples
// and in-betweens: the corpus is large): `play(name, index, session, key)` plays one, then the
// animation it started runs to its end (100 ticks at most).
template <typename Play>
void play_corpus(Play play)
{
    for (const auto& [name, bytes] : corpus_streams()) {
        MemoryFiles files = fuzzing::example_files();
        SessionSettings settings;
        settings.samples_per_segment = 4;
        settings.inbetween_count = 3;
        Session session(settings, files);
        for (std::size_t i = 0; i < bytes.size() && !session.finished(); ++i) {
            play(name, i, session, fuzzing::key_from(static_cast<std::uint8_t>(bytes[i])));
            for (int ticks = 0; session.animating() && ticks < 100; ++ticks)
                session.tick();
        }
    }
}

} // namespace

TEST_CASE("every key stream of the session fuzzing corpus plays without a crash and writes only in the folder",
          "[session][fuzz]")
{
    std::size_t streams = 0;
    std::size_t reached_fitting = 0;
    for (const auto& [name, bytes] : corpus_streams()) {
        const MemoryFiles files = fuzzing::play_keystrokes(
            {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
        ++streams;
        REQUIRE(fuzzing::writes_stay_in_folder(files));
        reached_fitting += files.files.count("inb001.dat");
    }
    REQUIRE(streams > 100);
    // The corpus reaches the end of the session, not only its first prompts.
    REQUIRE(reached_fitting > 0);
}

// A headless transcript draws a step's last screen only before a key that may end the step
// (Session::keeps_step): a key vouched for must never end it, or the transcript would print a
// screen the step never showed last.
TEST_CASE("a key the session vouches keeps its step never ends the step, over the whole fuzzing corpus",
          "[session][fuzz]")
{
    std::size_t vouched = 0;
    std::size_t changed_step = 0;
    play_corpus([&](const std::string& name, std::size_t i, Session& session, const KeyEvent& key) {
        const std::string_view before = session.step_title();
        const bool keeps = session.keeps_step(key);
        session.handle(key);
        if (keeps) {
            ++vouched;
            CAPTURE(name, i, before);
            REQUIRE(session.step_title() == before);
        }
        changed_step += session.step_title() != before;
    });
    // The corpus tries both: keys vouched for, and keys that end steps.
    REQUIRE(vouched > 10000);
    REQUIRE(changed_step > 1000);
}

// The terminal paints when the screen's revision has advanced (program_loop.cpp): a key that
// changes the screen without advancing it would leave the terminal showing what was, until some
// later key; one that advances it on an unchanged screen paints it again for nothing (a path of
// 10^6 points drawn anew).
TEST_CASE("over the whole fuzzing corpus, a key changes the session's screen if and only if it advances its "
          "revision",
          "[session][fuzz]")
{
    std::size_t changed = 0;
    std::size_t missed = 0;
    play_corpus([&](const std::string& name, std::size_t i, Session& session, const KeyEvent& key) {
        // The screen the key meets: the last key's and its animation's, or the session's first.
        const ProgramScreen shown = session.screen();
        const std::uint64_t revision = session.screen_revision();
        session.handle(key);
        const bool screen_changed = !(session.screen() == shown);
        const bool revision_advanced = session.screen_revision() != revision;
        changed += screen_changed ? 1 : 0;
        if (screen_changed != revision_advanced && ++missed <= 20)
            UNSCOPED_INFO(name << " key " << i << " at " << session.leaf_name() << ": the screen "
                               << (screen_changed ? "changed" : "stayed") << ", the revision "
                               << (revision_advanced ? "advanced" : "stayed"));
    });
    CHECK(missed == 0);
    REQUIRE(changed > 10000);
}
