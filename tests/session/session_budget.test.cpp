#include "apcs/formats/key_script.h"
#include "apcs/session/session.h"
#include "apcs/session/session_files.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>

using namespace apcs;
using apcs::test::type;

namespace {

std::string without_blanks(std::string text)
{
    std::erase(text, ' ');
    return text;
}

// Whether the text screen shows `message`. The console breaks a long message every 80 columns,
// at a blank or not: the screen's rows are joined and blanks left out on both sides.
bool shows(const Session& session, const std::string& message)
{
    const CellGrid grid = session.screen().text;
    std::string shown;
    for (int row = 0; row < grid.rows(); ++row)
        shown += grid.row_text(row);
    return without_blanks(shown).find(without_blanks(message)) != std::string::npos;
}

MemoryFiles example_files()
{
    MemoryFiles files;
    files.files["key1.dat"] = "0 0 0\n0 0 10\n0 6 0\n0 6 10\n";
    files.files["key2.dat"] = "0 0 10\n0 0 0\n0 5 0\n";
    files.files["way1.dat"] = "0 0 0\n3 -4 5\n1 1 7\n0 0 10\n";
    return files;
}

} // namespace

TEST_CASE("frames over the memory limit are refused after KEY2, which is asked again", "[session][memory]")
{
    MemoryFiles files = example_files();
    SessionSettings settings;
    settings.inbetween_count = 1000;
    // 1002 frames x 4 points x 24 + 4 x 608 = 98624 bytes.
    settings.memory_limit_bytes = 64 * 1024;
    Session session(settings, files);
    type(session, "key1.dat");
    type(session, "key2.dat");
    CHECK(session.leaf_name() == "ask_key2");
    CHECK(files.files.count("ani1.dat") == 0);
    CHECK(shows(session, "1002 frames of 4 points (--inbetweens 1000) need 96.3 KiB; the memory "
                                    "limit is 64 KiB (APCS_MEMORY_LIMIT); use key frames of fewer points, or start "
                                    "apcs with a lower --inbetweens"));
    // Keys within the limit go on.
    settings.inbetween_count = 12;
    Session allowed(settings, files);
    type(allowed, "key1.dat");
    type(allowed, "key2.dat");
    while (allowed.busy())
        allowed.work();
    CHECK(allowed.leaf_name() == "ask_view");
}

TEST_CASE("a path file over the memory limit is refused, and asked again", "[session][memory]")
{
    MemoryFiles files = example_files();
    // 200 control points from KEY1's first point to KEY2's: 200 x 320 + 12 x 48 = 64576 bytes
    // (curve samples are computed, not held: --samples does not count).
    std::string way;
    for (int k = 0; k < 200; ++k)
        way += "0 " + std::to_string(k % 199 % 5) + " " + std::to_string(k * 10.0 / 199) + "\n";
    files.files["way1.dat"] = way;
    SessionSettings settings;
    settings.samples_per_segment = 1000;
    settings.memory_limit_bytes = 40 * 1024;
    Session session(settings, files);
    type(session, "key1.dat");
    type(session, "key2.dat");
    while (session.busy())
        session.work();
    type(session, "");
    REQUIRE(session.leaf_name() == "ask_path_file");
    type(session, "way1.dat");
    CHECK(session.leaf_name() == "ask_path_file");
    CHECK(shows(session, "way1.dat: 200 control points x 1000 samples per segment (--samples) and 12 "
                                    "in-betweens (--inbetweens) need 63.1 KiB; the memory limit is 40 KiB "
                                    "(APCS_MEMORY_LIMIT); use a path of fewer control points, or start apcs with a "
                                    "lower --samples or --inbetweens"));
}

TEST_CASE("a key script's keys take one allocation of at most 8 bytes per byte of script", "[session][memory]")
{
    const std::string script = "TEXT " + std::string(1000, 'a') + "\n";
    const Expected<std::vector<KeyEvent>> keys = parse_key_script(script, "typed.keys");
    REQUIRE(keys);
    CHECK(keys->size() == 1000);
    CHECK(keys->capacity() * sizeof(KeyEvent) <= script.size() * 8);
    // Keys named by words leave no unused room behind either.
    std::string named;
    for (int i = 0; i < 1000; ++i)
        named += "BACKSPACE\n";
    const Expected<std::vector<KeyEvent>> words = parse_key_script(named, "named.keys");
    REQUIRE(words);
    CHECK(words->capacity() < 2 * words->size());
}

// A path from (0, 0, 0) to (0, 0, 10), KEY1's first point to KEY2's, of `count` control points.
std::string long_way(int count)
{
    std::string text = "0 0 0\n";
    for (int k = 1; k + 1 < count; ++k)
        text += std::to_string(k % 5) + " " + std::to_string(k % 3) + " " + std::to_string(k % 10) + "\n";
    return text + "0 0 10\n";
}

// Opening a 10^6-point path waited for 112 MB of arrays new to the process (PERFORMANCE.md 19);
// the terminal's session makes them while the slopes prompt waits, and the editor takes them.
TEST_CASE("the slopes prompt of a long path makes its evaluation's arrays while it waits", "[session][memory]")
{
    MemoryFiles files = example_files();
    constexpr int long_count = 70'000; // above the 65,536 points worth it
    files.files["long.dat"] = long_way(long_count);
    const auto at_slopes = [&files](Refinement refinement, const std::string& path) {
        SessionSettings settings;
        settings.refinement = refinement;
        auto session = std::make_unique<Session>(settings, files);
        for (const std::string answer : {"", "", "0 90 0", path.c_str()})
            type(*session, answer);
        REQUIRE(session->leaf_name() == "ask_slopes");
        return session;
    };
    std::unique_ptr<Session> terminal = at_slopes(Refinement::in_steps, "long.dat");
    REQUIRE(terminal->busy());
    REQUIRE(terminal->preparing());
    REQUIRE_FALSE(terminal->working()); // a replay routes keys as at any prompt
    terminal->work();
    REQUIRE_FALSE(terminal->busy());
    REQUIRE(terminal->leaf_name() == "ask_slopes");
    type(*terminal, "");
    REQUIRE(terminal->leaf_name() == "control_choice");
    REQUIRE(terminal->path_editor()->evaluated().curve.segments.size() == long_count - 1);
    // Headless (the whole picture at once) and a short path: the prompt never sets it to work.
    REQUIRE_FALSE(at_slopes(Refinement::at_once, "long.dat")->busy());
    REQUIRE_FALSE(at_slopes(Refinement::in_steps, "way1.dat")->busy());
}
