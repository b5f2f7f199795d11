#pragma once

#include <string>

namespace apcs {

// Where the session's steps note what they did (apcs.log): one line at a time.
class StepLog {
public:
    virtual ~StepLog() = default;
    virtual void log(const std::string& line) = 0;
};

// The batch commands and apcs play keep no session log.
class UnloggedSteps : public StepLog {
public:
    void log(const std::string&) override {}
};

} // namespace apcs
