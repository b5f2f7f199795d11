#pragma once

#include "apcs/lesson/replay_driver.h"
#include "apcs/session/session_files.h"

#include "support/temp_folder.h"

#include <filesystem>
#include <string>

namespace apcs::test {

inline const std::filesystem::path data_folder = std::filesystem::path(APCS_SOURCE_DIR) / "data";

// An example's files in memory, as the session reads them from its folder.
inline MemoryFiles example_files(const std::string& example)
{
    MemoryFiles files;
    for (const auto& entry : std::filesystem::directory_iterator(data_folder / example))
        if (entry.path().extension() == ".dat")
            files.files[entry.path().filename().string()] = read_all(entry.path());
    return files;
}

// What the terminal loop does while it waits for no key: the program's work, then its ticks.
inline void run_until_idle(ReplayDriver& replay)
{
    while (!replay.finished() && (replay.busy() || replay.animating())) {
        if (replay.busy())
            replay.work();
        else
            replay.tick();
    }
}

} // namespace apcs::test
