#include "fuzz/session_keystrokes.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <array>
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

// A session on the fuzzing example, with few samples and in-betweens: the corpus is large.
struct CorpusSession {
    MemoryFiles files = fuzzing::example_files();
    SessionSettings settings = [] {
        SessionSettings few;
        few.samples_per_segment = 4;
        few.inbetween_count = 3;
        return few;
    }();
    Session session{settings, files};

    // The animation the last key started, run to its end (100 ticks at most).
    void run_animation()
    {
        for (int ticks = 0; session.animating() && ticks < 100; ++ticks)
            session.tick();
    }
};

// Every key of every stream of the corpus, each stream played into a session of its own:
// `play(name, index, session, key)` plays one, then the animation it started runs to its end.
template <typename Play>
void play_corpus(Play play)
{
    for (const auto& [name, bytes] : corpus_streams()) {
        CorpusSession played;
        for (std::size_t i = 0; i < bytes.size() && !played.session.finished(); ++i) {
            play(name, i, played.session, fuzzing::key_from(static_cast<std::uint8_t>(bytes[i])));
            played.run_animation();
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

namespace {

// The terminal paints when the screen's revision has advanced (program_loop.cpp): a key that
// changes the screen without advancing it would leave the terminal showing what was, until some
// later key; one that advances it on an unchanged screen paints it again for nothing (a path of
// 10^6 points drawn anew). Each key judged: the screen and the revision before it, then after.
struct RepaintCheck {
    std::size_t changed = 0;
    std::size_t unpainted = 0; // the screen changed, the revision stayed
    std::size_t needless = 0;  // the revision advanced, the screen stayed

    void handle(Session& session, const KeyEvent& key, const std::string& where)
    {
        // The screen the key meets: the last key's and its animation's, or the session's first.
        const ProgramScreen shown = session.screen();
        const std::uint64_t revision = session.screen_revision();
        session.handle(key);
        const bool screen_changed = !(session.screen() == shown);
        const bool revision_advanced = session.screen_revision() != revision;
        changed += screen_changed ? 1 : 0;
        unpainted += screen_changed && !revision_advanced ? 1 : 0;
        needless += revision_advanced && !screen_changed ? 1 : 0;
        if (screen_changed != revision_advanced && unpainted + needless <= 20)
            UNSCOPED_INFO(where << " at " << session.leaf_name() << ": the screen "
                                << (screen_changed ? "changed" : "stayed") << ", the revision "
                                << (revision_advanced ? "advanced" : "stayed"));
    }
};

} // namespace

TEST_CASE("over the whole fuzzing corpus, a key changes the session's screen if and only if it advances its "
          "revision",
          "[session][fuzz]")
{
    RepaintCheck check;
    play_corpus([&](const std::string& name, std::size_t i, Session& session, const KeyEvent& key) {
        check.handle(session, key, name + " key " + std::to_string(i));
    });
    CHECK(check.unpainted == 0);
    CHECK(check.needless == 0);
    REQUIRE(check.changed > 10000);
}

// The corpus' bytes map to few of the path screen's keys (fuzz/session_keystrokes.h): from where
// each stream first opens the path screen, every key of its steps, the waypoint editor's and the
// field's, drawn at random (the same every run). A key that changes the screen always advances the
// revision. One that advances it on an unchanged screen costs a repaint: K in the waypoint editor
// (whose view stays) where the key frames light no pixel of the view not lit already, as a zoomed
// view away from them: 2 keys of these 9,000.
TEST_CASE("on the path screen, every key it has that changes the screen advances the revision, and nearly no other "
          "does",
          "[session][fuzz]")
{
    const std::array keys = {
        KeyEvent::of(Key::enter),     KeyEvent::of(Key::escape), KeyEvent::of(Key::tab),   KeyEvent::of(Key::back_tab),
        KeyEvent::of(Key::left),      KeyEvent::of(Key::right),  KeyEvent::of(Key::up),    KeyEvent::of(Key::down),
        KeyEvent::of(Key::backspace), KeyEvent::typed(U'U'),     KeyEvent::typed(U'G'),    KeyEvent::typed(U'Z'),
        KeyEvent::typed(U'O'),        KeyEvent::typed(U'C'),     KeyEvent::typed(U'T'),    KeyEvent::typed(U'K'),
        KeyEvent::typed(U'W'),        KeyEvent::typed(U'I'),     KeyEvent::typed(U'D'),    KeyEvent::typed(U'J'),
        KeyEvent::typed(U'L'),        KeyEvent::typed(U'='),     KeyEvent::typed(U'+'),    KeyEvent::typed(U'-'),
        KeyEvent::typed(U'['),        KeyEvent::typed(U']'),     KeyEvent::typed(U'8'),    KeyEvent::typed(U'2'),
        KeyEvent::typed(U'4'),        KeyEvent::typed(U'6'),     KeyEvent::typed(U'Y'),    KeyEvent::typed(U'N'),
        KeyEvent::typed(U'0'),        KeyEvent::typed(U'.'),     KeyEvent::typed(U'5'),    KeyEvent::typed(U'x'),
    };
    RepaintCheck check;
    std::size_t streams = 0;
    std::uint32_t draw = 7;
    for (const auto& [name, bytes] : corpus_streams()) {
        CorpusSession played;
        Session& session = played.session;
        for (std::size_t i = 0; i < bytes.size() && !session.finished() && session.path_editor() == nullptr; ++i) {
            session.handle(fuzzing::key_from(static_cast<std::uint8_t>(bytes[i])));
            played.run_animation();
        }
        if (session.path_editor() == nullptr)
            continue;
        for (int press = 0; press < 150 && !session.finished(); ++press) {
            draw = draw * 1103515245u + 12345u;
            check.handle(session, keys[(draw >> 16) % keys.size()], name + " path screen key " + std::to_string(press));
            played.run_animation();
        }
        if (++streams == 60)
            break;
    }
    CHECK(check.unpainted == 0);
    CHECK(check.needless <= 3);
    REQUIRE(streams == 60);
    REQUIRE(check.changed > 4000);
}
