#pragma once

#include <poll.h>
#include <pty.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <vector>

namespace apcs::bench {

// Runs `arguments` (the program's path first) in a new pseudo-terminal of `columns` x `rows`, as an
// xterm in a UTF-8 locale; returns the child's pid and sets `terminal` to the pseudo-terminal.
inline pid_t start_in_terminal(int& terminal, unsigned short columns, unsigned short rows,
                               const std::vector<std::string>& arguments)
{
    winsize size{rows, columns, 0, 0};
    const pid_t child = forkpty(&terminal, nullptr, nullptr, &size);
    if (child == 0) {
        setenv("TERM", "xterm", 1);
        setenv("LANG", "C.UTF-8", 1);
        std::vector<char*> argv;
        for (const std::string& argument : arguments)
            argv.push_back(const_cast<char*>(argument.c_str()));
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
    return child;
}

struct Drained {
    std::size_t bytes = 0;
    std::chrono::steady_clock::time_point last_byte; // when the last of them arrived
};

// Reads everything the program writes to the pseudo-terminal until it has been quiet for `quiet_ms`.
inline Drained drain(int terminal, int quiet_ms)
{
    Drained drained{0, std::chrono::steady_clock::now()};
    char buffer[65536];
    while (true) {
        pollfd ready{terminal, POLLIN, 0};
        if (poll(&ready, 1, quiet_ms) <= 0)
            return drained;
        const ssize_t got = read(terminal, buffer, sizeof buffer);
        if (got <= 0)
            return drained;
        drained.bytes += static_cast<std::size_t>(got);
        drained.last_byte = std::chrono::steady_clock::now();
    }
}

} // namespace apcs::bench
