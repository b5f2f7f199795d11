// libFuzzer harness: the session state machine fed random key streams over the N to L example
// kept in memory. It must never crash or hang, and every file it writes must be a plain name in
// its folder.
#include "apcs/session/session.h"

#include <cstdint>
#include <cstdlib>
#include <map>

namespace {

class FuzzFiles final : public apcs::SessionFiles {
public:
    std::map<std::string, std::string> files{
        {"key1.dat", "0 0 0\n0 0 10\n0 6 0\n0 6 10\n"},
        {"key2.dat", "0 0 10\n0 0 0\n0 5 0\n"},
        {"way1.dat", "0 0 0\n3 -4 5\n0 0 10\n"},
        {"ring.dat", "PART r CLOSED\n0 0 0\n1 0 0\n1 1 0\n"},
    };
    apcs::Expected<apcs::DatFile> read_dat(const std::string& name, std::size_t minimum_points) override
    {
        const auto found = files.find(name);
        if (found == files.end())
            return apcs::Diagnostic{name, 0, "cannot open"};
        return apcs::parse_dat(found->second, name, minimum_points);
    }
    std::optional<apcs::Diagnostic> write(const std::string& name, const std::string& content) override
    {
        if (name.empty() || name.front() == '/' || name.find("..") != std::string::npos)
            std::abort();
        // Bounded so that a long run does not grow without end.
        if (files.size() < 200)
            files[name] = content;
        return std::nullopt;
    }
    void log(const std::string&) override {}
};

apcs::KeyEvent key_from(std::uint8_t byte)
{
    using apcs::Key;
    using apcs::KeyEvent;
    // Mostly the keys a session understands, so that the stream reaches the later steps.
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

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    FuzzFiles files;
    apcs::SessionSettings settings;
    settings.samples_per_segment = 4;
    settings.inbetween_count = 3;
    apcs::Session session(settings, files);
    for (std::size_t i = 0; i < size && !session.finished(); ++i) {
        session.handle(key_from(data[i]));
        for (int ticks = 0; session.animating() && ticks < 100; ++ticks)
            session.tick();
        // Drawing every step would cost most of the time; every 32nd and the last one suffice
        // to reach the drawing code in every phase.
        if (i % 32 == 31)
            (void)session.screen();
    }
    (void)session.screen();
    return 0;
}
