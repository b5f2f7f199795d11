#pragma once

#include "apcs/cli/command_line.h"

#include <sstream>
#include <string>
#include <vector>

namespace apcs::test {

struct CommandRun {
    int status = 0;
    std::string out;
    std::string err;
};

// Runs the command line in-process, as `apcs ARGUMENTS…`.
inline CommandRun run_apcs(std::vector<std::string> arguments)
{
    arguments.insert(arguments.begin(), "apcs");
    std::vector<const char*> argv;
    for (const std::string& argument : arguments)
        argv.push_back(argument.c_str());
    std::ostringstream out;
    std::ostringstream err;
    const int status = run_command_line(static_cast<int>(argv.size()), argv.data(), out, err);
    return {status, out.str(), err.str()};
}

} // namespace apcs::test
