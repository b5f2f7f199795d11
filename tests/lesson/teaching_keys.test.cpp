// Random key streams through the path screen's teaching keys (T, G, Tab, =, W and the waypoint
// editor's keys, U): the session never crashes, never writes outside its folder, and every path it
// writes is a valid path file from the first graphic point's KEY1 to its KEY2 position.
#include "apcs/formats/dat_file.h"
#include "apcs/session/session.h"
#include "apcs/session/session_files.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <random>

using namespace apcs;

namespace {

KeyEvent teaching_key(std::mt19937& random)
{
    static constexpr char32_t typed[] = {U'8', U'2', U'4', U'6', U'J', U'L', U'Y', U'N', U'K', U'T', U'G', U'=',
                                         U'W', U'U', U'I', U'D', U'[', U']', U'+', U'-', U'0', U'.', U'5', U'x'};
    static constexpr Key keys[] = {Key::enter, Key::escape, Key::tab, Key::back_tab, Key::left, Key::right,
                                   Key::up, Key::down, Key::backspace};
    std::uniform_int_distribution<std::size_t> pick(0, std::size(typed) + std::size(keys) - 1);
    const std::size_t index = pick(random);
    return index < std::size(typed) ? KeyEvent::typed(typed[index]) : KeyEvent::of(keys[index - std::size(typed)]);
}

} // namespace

TEST_CASE("random keys on the path screen's teaching keys never break the session or its path files",
          "[session][teaching][random]")
{
    std::mt19937 random(20261122);
    std::size_t accepted = 0;
    std::size_t reshaped = 0;
    for (int stream = 0; stream < 200; ++stream) {
        MemoryFiles files;
        files.files["key1.dat"] = "0 0 0\n0 6 0\n";
        files.files["key2.dat"] = "0 0 10\n0 6 10\n";
        files.files["way.dat"] = "; way\n0 0 0\n1 2 5 ; middle\n0 0 10\n";
        SessionSettings settings;
        settings.samples_per_segment = 4;
        settings.inbetween_count = 3;
        Session session(settings, files);
        for (const char* answer : {"", "", "", "way.dat", ""})
            test::type(session, answer);
        REQUIRE(session.leaf_name() == "control_choice");
        for (int key = 0; key < 300 && !session.finished() && session.leaf_name() != "ask_next_path"; ++key) {
            session.handle(teaching_key(random));
            if (key % 16 == 0)
                (void)session.screen();
        }
        (void)session.screen();
        for (const std::string& name : files.writes)
            REQUIRE((name == "way.dat" || name.starts_with("ani") || name.starts_with("apcs")));
        if (session.leaf_name() != "ask_next_path")
            continue;
        ++accepted;
        const Expected<DatFile> written = parse_dat(files.files["way.dat"], "way.dat");
        REQUIRE(written);
        const auto& points = written->parts.front().points;
        REQUIRE(points.front().position == Vec3{0, 0, 0});
        REQUIRE(points.back().position == Vec3{0, 0, 10});
        REQUIRE(files.files["way.dat"].starts_with("; way\n"));
        reshaped += points.size() != 3 ? 1u : 0u;
    }
    // The streams reach the end of the path step, not only its first keys.
    REQUIRE(accepted > 20);
    // ... and the waypoint editor's changes reach the file.
    REQUIRE(reshaped > 0);
}
