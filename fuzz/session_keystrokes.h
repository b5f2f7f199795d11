#pragma once

// The session driven by a stream of bytes, one key each: shared by the libFuzzer harness and the
// Catch test that replays its corpus, so both play the same sessions.

#include "apcs/session/session.h"
#include "apcs/session/session_files.h"

#include <cstdint>
#include <span>

namespace apcs::fuzzing {

// Mostly the keys a session understands, so that the stream reaches the later steps.
inline KeyEvent key_from(std::uint8_t byte)
{
    static constexpr char32_t typed[] = {U'8', U'2', U'4', U'6', U'J', U'L', U'Y', U'N', U'R', U'K', U'1',
                                         U'0', U'.', U'w', U'a', U'y', U'd', U't', U'k', U'e', U'r', U'i'};
    switch (byte % 32) {
    case 0: case 1: case 2: case 3: case 4: return KeyEvent::of(Key::enter);
    case 5: return KeyEvent::of(Key::escape);
    case 6: return KeyEvent::of(Key::space);
    case 7: return KeyEvent::of(Key::left);
    case 8: return KeyEvent::of(Key::right);
    case 9: return KeyEvent::of(Key::backspace);
    default: return KeyEvent::typed(typed[(byte / 32 + byte) % (sizeof typed / sizeof typed[0])]);
    }
}

// The N to L example, and a closed ring, kept in memory.
inline MemoryFiles example_files()
{
    MemoryFiles files;
    files.files = {
        {"key1.dat", "0 0 0\n0 0 10\n0 6 0\n0 6 10\n"},
        {"key2.dat", "0 0 10\n0 0 0\n0 5 0\n"},
        {"way1.dat", "0 0 0\n3 -4 5\n0 0 10\n"},
        {"ring.dat", "PART r CLOSED\n0 0 0\n1 0 0\n1 1 0\n"},
    };
    return files;
}

// Plays `bytes` as keys over example_files() and returns the files as the session left them.
inline MemoryFiles play_keystrokes(std::span<const std::uint8_t> bytes)
{
    MemoryFiles files = example_files();
    SessionSettings settings;
    settings.samples_per_segment = 4;
    settings.inbetween_count = 3;
    Session session(settings, files);
    for (std::size_t i = 0; i < bytes.size() && !session.finished(); ++i) {
        session.handle(key_from(bytes[i]));
        for (int ticks = 0; session.animating() && ticks < 100; ++ticks)
            session.tick();
        // Drawing every step would cost most of the time; every 32nd and the last one suffice
        // to reach the drawing code in every phase.
        if (i % 32 == 31)
            (void)session.screen();
    }
    (void)session.screen();
    return files;
}

// Every file a session writes is a plain name in its folder.
inline bool writes_stay_in_folder(const MemoryFiles& files)
{
    for (const std::string& name : files.writes)
        if (name.empty() || name.front() == '/' || name.find("..") != std::string::npos)
            return false;
    return true;
}

} // namespace apcs::fuzzing
