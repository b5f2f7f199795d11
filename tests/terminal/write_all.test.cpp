#include "src/terminal/write_all.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <string>
#include <sys/resource.h>
#include <thread>
#include <unistd.h>

using namespace apcs;

namespace {

// The CPU time the calling thread has used.
std::chrono::microseconds thread_cpu_time()
{
    rusage usage{};
    getrusage(RUSAGE_THREAD, &usage);
    return std::chrono::seconds(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           std::chrono::microseconds(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// A pipe whose writing end is non-blocking and full, as a terminal's output is when Ctrl-S holds
// it: how many bytes it holds.
std::size_t fill(int fd)
{
    const std::string chunk(4096, 'x');
    std::size_t held = 0;
    for (ssize_t written = 0; (written = ::write(fd, chunk.data(), chunk.size())) > 0;)
        held += static_cast<std::size_t>(written);
    return held;
}

struct Pipe {
    int read_end = -1;
    int write_end = -1;
    Pipe()
    {
        int ends[2] = {-1, -1};
        REQUIRE(::pipe(ends) == 0);
        read_end = ends[0];
        write_end = ends[1];
    }
    ~Pipe()
    {
        ::close(read_end);
        ::close(write_end);
    }
};

} // namespace

TEST_CASE("a full non-blocking terminal is waited for, not written to in a spin", "[terminal]")
{
    Pipe pipe;
    REQUIRE(::fcntl(pipe.write_end, F_SETFL, O_NONBLOCK) == 0);
    const std::size_t held = fill(pipe.write_end);
    const std::string picture(100000, 'p');
    const auto reader_wait = std::chrono::milliseconds(400);
    std::size_t read_back = 0;
    std::thread reader([&] {
        std::this_thread::sleep_for(reader_wait);
        char buffer[8192];
        while (read_back < held + picture.size()) {
            const ssize_t got = ::read(pipe.read_end, buffer, sizeof buffer);
            if (got <= 0)
                break;
            read_back += static_cast<std::size_t>(got);
        }
    });
    const auto cpu_before = thread_cpu_time();
    const bool written = write_all(pipe.write_end, picture);
    const auto cpu_used = thread_cpu_time() - cpu_before;
    reader.join();
    REQUIRE(written);
    REQUIRE(read_back == held + picture.size());
    // Retrying EAGAIN at once used the whole wait's CPU (about 400 ms); waiting in poll, almost none.
    INFO("CPU used while the reader waited " << reader_wait.count() << " ms: " << cpu_used.count() << " us");
    REQUIRE(cpu_used < std::chrono::milliseconds(100));
}

TEST_CASE("a wait for room ends when give_up says so, and a closed terminal is no wait at all", "[terminal]")
{
    Pipe pipe;
    REQUIRE(::fcntl(pipe.write_end, F_SETFL, O_NONBLOCK) == 0);
    fill(pipe.write_end);
    int asked = 0;
    REQUIRE_FALSE(write_all(pipe.write_end, "more", [&asked] { return ++asked == 3; }));
    REQUIRE(asked == 3);

    ::close(pipe.read_end);
    pipe.read_end = ::open("/dev/null", O_RDONLY);
    // EPIPE: SIGPIPE is ignored for this write (as the session's terminal handles it itself).
    struct sigaction ignore {};
    struct sigaction old {};
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &old);
    const bool written = write_all(pipe.write_end, "more");
    sigaction(SIGPIPE, &old, nullptr);
    REQUIRE_FALSE(written);
}
