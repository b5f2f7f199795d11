#include "write_all.h"

#include <cerrno>
#include <poll.h>
#include <unistd.h>

namespace apcs {

namespace {

// How long one wait for room lasts before `give_up` is asked again.
constexpr int room_wait_ms = 100;

} // namespace

bool write_all(int fd, std::string_view bytes, const std::function<bool()>& give_up)
{
    while (!bytes.empty()) {
        const ssize_t written = ::write(fd, bytes.data(), bytes.size());
        if (written >= 0) {
            bytes.remove_prefix(static_cast<std::size_t>(written));
            continue;
        }
        if (errno == EINTR)
            continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK)
            return false; // the terminal is gone: read_key will say so
        if (give_up && give_up())
            return false;
        pollfd output{fd, POLLOUT, 0};
        if (::poll(&output, 1, room_wait_ms) < 0 && errno != EINTR)
            return false;
    }
    return true;
}

} // namespace apcs
