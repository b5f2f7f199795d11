// apcs play end to end in a pseudo-terminal: the real program plays a scene with --delay 0, so
// each frame costs only its computing, drawing and writing; the time from start until the last
// byte of the overlay, over the frames, bounds a frame's cost from above (start-up and the
// overlay included). Also the bytes sent per frame (what a slow SSH link must carry).
// Usage: play_terminal PATH_TO_APCS SCENE.scn [ROUNDS]
#include "pty_reading.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

struct Play {
    double milliseconds = 0;
    std::size_t bytes = 0;
};

Play play_once(const std::string& apcs, const std::string& scene, unsigned short columns, unsigned short rows,
               const char* glyphs)
{
    int terminal = -1;
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = apcs::bench::start_in_terminal(
        terminal, columns, rows, {apcs, "play", scene, "--delay", "0", "--glyphs", glyphs});
    const apcs::bench::Drained played = apcs::bench::drain(terminal, 500);
    (void)!write(terminal, "q", 1);
    apcs::bench::drain(terminal, 200);
    kill(child, SIGTERM);
    waitpid(child, nullptr, 0);
    close(terminal);
    return {std::chrono::duration<double, std::milli>(played.last_byte - start).count(), played.bytes};
}

int scene_frames(const std::string& scene)
{
    std::ifstream file(scene);
    std::string word;
    int frames = 0;
    while (file >> word)
        if (word == "FRAMES" && file >> frames)
            return frames + 1; // frames 0 … N
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 3 || argc > 4) {
        std::fprintf(stderr, "usage: play_terminal PATH_TO_APCS SCENE.scn [ROUNDS]\n");
        return 2;
    }
    const int frames = scene_frames(argv[2]);
    const int rounds = argc == 4 ? std::max(1, std::atoi(argv[3])) : 5;
    if (frames <= 0) {
        std::fprintf(stderr, "%s: no FRAMES line\n", argv[2]);
        return 2;
    }
    std::printf("%d frames, --delay 0, %d rounds; per frame: wall time (median, min, max) and bytes\n", frames,
                rounds);
    for (const auto& [columns, rows] : {std::pair<unsigned short, unsigned short>{80, 24}, {200, 60}})
        for (const char* glyphs : {"ascii", "braille"}) {
            std::vector<double> times;
            std::size_t bytes = 0;
            for (int round = 0; round < rounds; ++round) {
                const Play play = play_once(argv[1], argv[2], columns, rows, glyphs);
                times.push_back(play.milliseconds / frames);
                bytes = play.bytes;
            }
            std::sort(times.begin(), times.end());
            std::printf("%3dx%-3d %-8s %7.3f ms  (%.3f … %.3f)  %6zu B\n", columns, rows, glyphs,
                        times[times.size() / 2], times.front(), times.back(), bytes / static_cast<std::size_t>(frames));
        }
    return 0;
}
