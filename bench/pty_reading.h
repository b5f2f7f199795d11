#pragma once

#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>

namespace apcs::bench {

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
