#pragma once

#include <functional>
#include <string_view>

namespace apcs {

// Writes all of `bytes` to `fd`: again after a signal cut a write short, and, when the descriptor
// is non-blocking and full (a terminal's output held by Ctrl-S or a slow link), once poll says it
// takes more, instead of retrying at once and spinning a core. `give_up`, asked while waiting,
// ends the wait (a stop requested). False when the bytes could not all be written.
bool write_all(int fd, std::string_view bytes, const std::function<bool()>& give_up = {});

} // namespace apcs
