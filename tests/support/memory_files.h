#pragma once

#include "apcs/session/session_files.h"

#include <map>
#include <string>
#include <vector>

namespace apcs::test {

// Session files kept in memory: what a session reads, writes and logs, with no disk.
class MemoryFiles final : public SessionFiles {
public:
    std::map<std::string, std::string> files;
    std::vector<std::string> log_lines;
    std::vector<std::string> writes;

    Expected<DatFile> read_dat(const std::string& name, std::size_t minimum_points) override
    {
        const auto found = files.find(name);
        if (found == files.end())
            return Diagnostic{name, 0, "cannot open: No such file or directory"};
        return parse_dat(found->second, name, minimum_points);
    }
    std::optional<Diagnostic> write(const std::string& name, const std::string& content) override
    {
        files[name] = content;
        writes.push_back(name);
        return std::nullopt;
    }
    void log(const std::string& line) override { log_lines.push_back(line); }
};

} // namespace apcs::test
