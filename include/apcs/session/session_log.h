#pragma once

#include <string>

namespace apcs {

// Where the session's steps note what they did (apcs.log): one line at a time.
class SessionLog {
public:
    virtual ~SessionLog() = default;
    virtual void log(const std::string& line) = 0;
};

} // namespace apcs
