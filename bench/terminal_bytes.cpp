// Counts the bytes APCS sends to an 80x24 terminal for each staff keystroke: the real program in
// a pseudo-terminal, a 6-point path, 20 presses of 6 on TENSION, for each glyph set.
// Usage: terminal_bytes PATH_TO_APCS
#include "pty_reading.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

void type(int terminal, const std::string& keys, int quiet_ms = 150)
{
    (void)!write(terminal, keys.data(), keys.size());
    apcs::bench::drain(terminal, quiet_ms);
}

std::vector<std::size_t> measure(const std::string& apcs, const std::filesystem::path& folder, const char* glyphs)
{
    int terminal = -1;
    const pid_t child =
        apcs::bench::start_in_terminal(terminal, 80, 24, {apcs, "--workdir", folder.string(), "--glyphs", glyphs});
    apcs::bench::drain(terminal, 300);
    type(terminal, "\r");             // key1.dat
    type(terminal, "\r");             // key2.dat
    type(terminal, "0 90 0\r");       // view
    type(terminal, "way1.dat\r");     // the 6-point path
    type(terminal, "\r");             // slopes 1 1
    type(terminal, "8", 300);         // global control: the staff
    std::vector<std::size_t> bytes;
    for (int press = 0; press < 20; ++press) {
        (void)!write(terminal, "6", 1);
        bytes.push_back(apcs::bench::drain(terminal, 150).bytes);
    }
    kill(child, SIGTERM);
    apcs::bench::drain(terminal, 100);
    waitpid(child, nullptr, 0);
    close(terminal);
    return bytes;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: terminal_bytes PATH_TO_APCS\n");
        return 2;
    }
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("apcs-bytes-" + std::to_string(getpid()));
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "key1.dat") << "0 0 0\n1 0 0\n";
    std::ofstream(folder / "key2.dat") << "0 10 6\n1 10 6\n";
    std::ofstream(folder / "way1.dat") << "0 0 0\n0 2 3\n0 4 1\n0 6 4\n0 8 2\n0 10 6\n";
    std::printf("glyphs   median  min  max   bytes per press of 6 on TENSION (20 presses, 80x24)\n");
    for (const char* glyphs : {"ascii", "braille", "blocks"}) {
        std::vector<std::size_t> bytes = measure(argv[1], folder, glyphs);
        std::vector<std::size_t> sorted = bytes;
        std::sort(sorted.begin(), sorted.end());
        const double median = static_cast<double>(sorted[9] + sorted[10]) / 2.0;
        std::printf("%-8s %6.0f %4zu %4zu  ", glyphs, median, sorted.front(), sorted.back());
        for (const std::size_t count : bytes)
            std::printf(" %zu", count);
        std::printf("\n");
    }
    std::filesystem::remove_all(folder);
    return 0;
}
