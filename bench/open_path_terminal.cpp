// What a person waits for when opening a long path: the real program in an 80x24 pseudo-terminal,
// its output read by a VT emulator (libvterm), so a screen counts as shown when the emulated
// terminal shows it, not when the program has computed it. For a path of N control points (10^6
// by default, 33 MB, written once to a temporary folder) and each spacing, each run times
//   reading: Enter on the path file's name until the slopes prompt is on the screen;
//   opening:  Enter on the slopes until the path screen's first picture is on the screen (its
//             staff and key line; with exact spacing its message line says the arc lengths are
//             being measured, and the in-betweens come when they are);
//   8/2:      Enter on the slopes until the 8/2 choice stands on that line: the final picture;
//   a key:    a staff key under global control (6, 4, Shift-L and Shift-J in turn, on each of the
//             four staff lines, Enter going on to the next; each key after the previous one's
//             picture is finished) until its first picture is on the screen.
// A screen is on the screen when the emulated terminal holds it and the burst of bytes that drew
// it has ended (no byte for 3 ms: a refinement step, ~10 ms of work, comes later).
// The slopes are answered (Enter) PROMPT_MS after their prompt is on the screen (1000 by default: a
// person reads it; the program prepares the opening meanwhile), and no sooner than 200 ms after the
// terminal fell quiet.
// Usage: open_path_terminal PATH_TO_APCS [RUNS] [POINTS] [PROMPT_MS] (every figure is printed, then
// medians)
#include "pty_reading.h"

#include <vterm.h>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_between(Clock::time_point from, Clock::time_point to)
{
    return std::chrono::duration<double, std::milli>(to - from).count();
}

// The program in a pseudo-terminal and the emulated terminal that reads it.
class EmulatedTerminal {
public:
    EmulatedTerminal(const std::string& apcs, const std::filesystem::path& folder, const char* spacing)
        : m_vterm(vterm_new(rows, columns))
    {
        vterm_set_utf8(m_vterm, 1);
        m_screen = vterm_obtain_screen(m_vterm);
        vterm_screen_enable_altscreen(m_screen, 1);
        vterm_screen_reset(m_screen, 1);
        m_child = apcs::bench::start_in_terminal(
            m_pty, columns, rows, {apcs, "--workdir", folder.string(), "--glyphs", "ascii", "--spacing", spacing});
    }
    EmulatedTerminal(const EmulatedTerminal&) = delete;
    EmulatedTerminal& operator=(const EmulatedTerminal&) = delete;
    ~EmulatedTerminal()
    {
        kill(m_child, SIGTERM);
        read_for(100);
        waitpid(m_child, nullptr, 0);
        close(m_pty);
        vterm_free(m_vterm);
    }

    // Writes `keys` and returns when they were written.
    Clock::time_point type(const std::string& keys)
    {
        const Clock::time_point written = Clock::now();
        (void)!write(m_pty, keys.data(), keys.size());
        return written;
    }

    // The screen's text, its rows joined by '\n'.
    std::string text() const
    {
        std::vector<char> buffer(static_cast<std::size_t>(rows) * (columns * 4 + 1));
        std::string all;
        for (int row = 0; row < rows; ++row) {
            const VTermRect line{row, row + 1, 0, columns};
            const std::size_t length = vterm_screen_get_text(m_screen, buffer.data(), buffer.size(), line);
            all.append(buffer.data(), length);
            all += '\n';
        }
        return all;
    }

    // Reads until the screen satisfies `shown` and the burst that drew it has ended; the time of the
    // burst's last byte (the last burst's, when the screen already satisfies it), or nothing after
    // `limit_ms`.
    std::optional<Clock::time_point> wait_until(const std::function<bool(const std::string&)>& shown, int limit_ms)
    {
        if (shown(text()))
            return m_last_byte;
        const Clock::time_point give_up = Clock::now() + std::chrono::milliseconds(limit_ms);
        while (Clock::now() < give_up) {
            if (!read_some(static_cast<int>(milliseconds_between(Clock::now(), give_up)) + 1))
                continue;
            if (shown(text()))
                return end_of_burst();
        }
        return std::nullopt;
    }

    // Reads until nothing has come for `quiet_ms`.
    void read_for(int quiet_ms)
    {
        while (read_some(quiet_ms)) {
        }
    }

private:
    static constexpr unsigned short rows = 24;
    static constexpr unsigned short columns = 80;

    bool read_some(int wait_ms)
    {
        pollfd ready{m_pty, POLLIN, 0};
        if (poll(&ready, 1, wait_ms) <= 0)
            return false;
        char buffer[65536];
        const ssize_t got = read(m_pty, buffer, sizeof buffer);
        if (got <= 0)
            return false;
        m_last_byte = Clock::now();
        vterm_input_write(m_vterm, buffer, static_cast<std::size_t>(got));
        return true;
    }

    Clock::time_point end_of_burst()
    {
        constexpr int burst_gap_ms = 3;
        while (read_some(burst_gap_ms)) {
        }
        return m_last_byte;
    }

    VTerm* m_vterm;
    VTermScreen* m_screen = nullptr;
    int m_pty = -1;
    pid_t m_child = -1;
    Clock::time_point m_last_byte = Clock::now();
};

bool contains(const std::string& text, const char* wanted) { return text.find(wanted) != std::string::npos; }

constexpr std::array<const char*, 4> staff_lines{"TENSION", "CONTINUITY", "BIAS", "ACCELERATION"};
constexpr std::array<const char*, 4> staff_keys{"6", "4", "L", "J"};

// A line of the staff (the row that starts with its name after the ">" column; the message line
// above names it too), for telling a key's picture from the one before it.
std::string staff_line(const std::string& screen, const char* name)
{
    for (std::size_t row = 0; row < screen.size();) {
        const std::size_t end = std::min(screen.find('\n', row), screen.size());
        const std::string_view line(screen.data() + row, end - row);
        if (line.size() > 1 && line.substr(1).starts_with(name))
            return std::string(line);
        row = end + 1;
    }
    return {};
}

// The picture is finished when no refinement message is left and the terminal has been quiet.
void wait_for_final_picture(EmulatedTerminal& terminal)
{
    terminal.wait_until(
        [](const std::string& screen) { return !contains(screen, "drawing the curve") && !contains(screen, "measuring arc"); },
        60000);
    terminal.read_for(300);
}

struct Run {
    double reading_ms = 0;
    double opening_ms = 0;
    double choice_ms = 0;
    std::array<std::vector<double>, staff_lines.size()> key_ms; // a staff line's keys
};

std::optional<Run> run_once(const std::string& apcs, const std::filesystem::path& folder, const char* spacing, int keys,
                            int prompt_ms)
{
    EmulatedTerminal terminal(apcs, folder, spacing);
    const auto prompt_with = [&terminal](const char* wanted) {
        return terminal.wait_until([wanted](const std::string& screen) { return contains(screen, wanted); }, 20000);
    };
    if (!prompt_with("KEY1"))
        return std::nullopt;
    terminal.read_for(200);
    for (const char* answer : {"\r", "\r", "0 90 0\r"}) {
        terminal.type(answer);
        terminal.read_for(200);
    }
    Run run;
    Clock::time_point entered = terminal.type("way1.dat\r");
    const std::optional<Clock::time_point> slopes_shown = prompt_with("DS[0]");
    if (!slopes_shown)
        return std::nullopt;
    run.reading_ms = milliseconds_between(entered, *slopes_shown);
    terminal.read_for(200);
    const int read_so_far = static_cast<int>(milliseconds_between(*slopes_shown, Clock::now()));
    if (read_so_far < prompt_ms)
        terminal.wait_until([](const std::string&) { return false; }, prompt_ms - read_so_far);
    entered = terminal.type("\r");
    const std::optional<Clock::time_point> path_shown = prompt_with("W waypoints");
    const std::optional<Clock::time_point> choice_shown = prompt_with("8 : Global Control");
    if (!path_shown || !choice_shown)
        return std::nullopt;
    run.opening_ms = milliseconds_between(entered, *path_shown);
    run.choice_ms = milliseconds_between(entered, *choice_shown);
    wait_for_final_picture(terminal);
    terminal.type("8");
    wait_for_final_picture(terminal);
    for (std::size_t line = 0; line < staff_lines.size(); ++line) {
        const char* name = staff_lines[line];
        for (int key = 0; key < keys; ++key) {
            const std::string before = staff_line(terminal.text(), name);
            entered = terminal.type(staff_keys[static_cast<std::size_t>(key) % staff_keys.size()]);
            const std::optional<Clock::time_point> key_shown = terminal.wait_until(
                [&](const std::string& screen) { return staff_line(screen, name) != before; }, 20000);
            if (!key_shown) {
                std::fprintf(stderr, "%s key %d: the line did not change:\n%s\n", name, key, terminal.text().c_str());
                return std::nullopt;
            }
            run.key_ms[line].push_back(milliseconds_between(entered, *key_shown));
            wait_for_final_picture(terminal);
        }
        terminal.type("\r");
        wait_for_final_picture(terminal);
    }
    return run;
}

// The trajectory of PERFORMANCE.md section 9, with key frames whose first points are its ends.
void write_session_files(const std::filesystem::path& folder, long points)
{
    std::filesystem::create_directories(folder);
    const auto point_at = [](long i) {
        const double t = static_cast<double>(i);
        return std::vector<double>{std::sin(t * 0.9) * 3.0, t * 2.0, std::cos(t * 0.7) * 4.0};
    };
    const auto line = [](const std::vector<double>& p) {
        char text[96];
        std::snprintf(text, sizeof text, "%.6f %.6f %.6f\n", p[0], p[1], p[2]);
        return std::string(text);
    };
    std::ofstream path(folder / "way1.dat", std::ios::binary);
    for (long i = 0; i < points; ++i)
        path << line(point_at(i));
    path.close();
    // The ends as the file holds them (6 decimals), so that they meet the key frames exactly.
    std::ofstream(folder / "key1.dat") << line(point_at(0)) << "1 0 0\n";
    std::ofstream(folder / "key2.dat") << line(point_at(points - 1)) << "1 10 6\n";
}

double median(std::vector<double> values)
{
    if (values.empty())
        return 0;
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 5) {
        std::fprintf(stderr, "usage: open_path_terminal PATH_TO_APCS [RUNS] [POINTS] [PROMPT_MS]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
    const long points = argc > 3 ? std::atol(argv[3]) : 1'000'000;
    const int prompt_ms = argc > 4 ? std::atoi(argv[4]) : 1000;
    constexpr int keys_a_run = 6;
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("apcs-open-" + std::to_string(getpid()));
    write_session_files(folder, points);
    std::printf("%ld control points, 80x24, %d runs a spacing, the slopes answered %d ms after their prompt, %d keys "
                "a staff line a run (ms)\n",
                points, runs, prompt_ms, keys_a_run);
    int failures = 0;
    for (const char* spacing : {"nearest", "exact"}) {
        std::vector<double> reading, opening, choice, all_keys;
        std::array<std::vector<double>, staff_lines.size()> line_keys;
        for (int run = 0; run < runs; ++run) {
            const std::optional<Run> measured = run_once(argv[1], folder, spacing, keys_a_run, prompt_ms);
            if (!measured) {
                std::printf("%-8s run %d: a screen did not come\n", spacing, run + 1);
                ++failures;
                continue;
            }
            std::printf("%-8s run %d: reading %7.1f  opening %7.1f  8/2 %7.1f\n", spacing, run + 1,
                        measured->reading_ms, measured->opening_ms, measured->choice_ms);
            for (std::size_t line = 0; line < staff_lines.size(); ++line) {
                std::printf("%-8s run %d: %-12s keys", spacing, run + 1, staff_lines[line]);
                for (const double ms : measured->key_ms[line])
                    std::printf(" %5.1f", ms);
                std::printf("\n");
                line_keys[line].insert(line_keys[line].end(), measured->key_ms[line].begin(), measured->key_ms[line].end());
                all_keys.insert(all_keys.end(), measured->key_ms[line].begin(), measured->key_ms[line].end());
            }
            reading.push_back(measured->reading_ms);
            opening.push_back(measured->opening_ms);
            choice.push_back(measured->choice_ms);
        }
        std::printf("%-8s median: reading %7.1f  opening %7.1f  8/2 %7.1f  key's first picture %5.1f (", spacing,
                    median(reading), median(opening), median(choice), median(all_keys));
        for (std::size_t line = 0; line < staff_lines.size(); ++line)
            std::printf("%s%s %.1f", line == 0 ? "" : ", ", staff_lines[line], median(line_keys[line]));
        const auto slowest = std::max_element(all_keys.begin(), all_keys.end());
        std::printf("; slowest %.1f)\n", slowest == all_keys.end() ? 0.0 : *slowest);
    }
    std::filesystem::remove_all(folder);
    return failures == 0 ? 0 : 1;
}
