#pragma once

#include "apcs/input/play_to_idle.h"
#include "apcs/lesson/replay_driver.h"
#include "apcs/session/session_files.h"

#include "support/session_keys.h"
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

// A key script of the source tree, parsed with its captions, goals and inputs.
inline KeyScript read_script(const std::filesystem::path& file)
{
    Expected<KeyScript> script = parse_captioned_key_script(read_all(file), file.string());
    REQUIRE(script);
    return std::move(*script);
}

// The message line of what a replay shows: a GOAL's feedback stands there (SPEC §3.1), the task's
// caption on the caption row above it.
inline std::string message_line(const ReplayDriver& replay)
{
    const ProgramScreen screen = replay.screen();
    if (screen.graphics)
        return message_of(screen.picture);
    std::string row = screen.text.row_text(screen.text.rows() - 1);
    row.erase(row.find_last_not_of(' ') + 1);
    return row;
}

inline bool at_goal_feedback(const ReplayDriver& replay) { return message_line(replay).starts_with("GOAL: "); }

} // namespace apcs::test
