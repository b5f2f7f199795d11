#pragma once

#include "apcs/formats/dat_file.h"
#include "apcs/formats/diagnostic.h"
#include "apcs/session/session_log.h"

#include <filesystem>
#include <optional>
#include <string>

namespace apcs {

// The session's only door to files, so that its state machine stays free of I/O and can be
// driven in tests with any store.
class SessionFiles : public SessionLog {
public:
    virtual Expected<DatFile> read_dat(const std::string& name, std::size_t minimum_points) = 0;
    // Atomic, keeping a differing old file as .bak; the problem, if any.
    virtual std::optional<Diagnostic> write(const std::string& name, const std::string& content) = 0;
};

// Files in a folder: names are relative to it (an absolute name is used as it is); apcs.log is
// appended to there.
class FolderFiles final : public SessionFiles {
public:
    explicit FolderFiles(std::filesystem::path folder) : m_folder(std::move(folder)) {}

    Expected<DatFile> read_dat(const std::string& name, std::size_t minimum_points) override;
    std::optional<Diagnostic> write(const std::string& name, const std::string& content) override;
    void log(const std::string& line) override;

private:
    std::filesystem::path m_folder;
};

} // namespace apcs
