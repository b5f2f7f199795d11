#include "apcs/cli/data_folder.h"

#include "apcs/formats/file_io.h"

#include <cstdlib>
#include <string>
#include <system_error>

namespace apcs {

namespace {

std::filesystem::path canonical_or_empty(const std::filesystem::path& path)
{
    std::error_code error;
    std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    return error ? std::filesystem::path{} : canonical;
}

} // namespace

Expected<std::filesystem::path> choose_data_folder(const DataFolderClues& clues,
                                                   const std::function<bool(const std::filesystem::path&)>& is_folder)
{
    const std::string expected = "expected the folder that holds the examples n-to-l/, stick/, snake-apple/ and robot/";
    if (!clues.environment.empty()) {
        if (is_folder(clues.environment))
            return clues.environment;
        return Diagnostic{"APCS_DATA", 0, clues.environment.string() + " is not a folder; " + expected};
    }
    std::string looked_in;
    if (!clues.executable.empty()) {
        const std::filesystem::path installed = clues.executable.parent_path().parent_path() / "share" / "apcs";
        if (is_folder(installed))
            return installed;
        looked_in = installed.string();
    }
    if (!clues.build_folder.empty() && lies_within(clues.executable, clues.build_folder)) {
        if (is_folder(clues.source_data))
            return clues.source_data;
        looked_in += (looked_in.empty() ? "" : " and ") + clues.source_data.string();
    }
    return Diagnostic{"apcs", 0,
                      "the examples are not installed (looked in " + (looked_in.empty() ? "no folder" : looked_in) +
                          "); set APCS_DATA to the folder that holds n-to-l/, stick/, snake-apple/ and robot/, or give --workdir"};
}

DataFolderClues running_program_clues()
{
    DataFolderClues clues;
    if (const char* environment = std::getenv("APCS_DATA"))
        clues.environment = environment;
    std::error_code error;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error)
        clues.executable = executable;
    clues.build_folder = canonical_or_empty(APCS_BUILD_DIR);
    clues.source_data = APCS_SOURCE_DATA_DIR;
    return clues;
}

Expected<std::filesystem::path> find_data_folder()
{
    return choose_data_folder(running_program_clues(), [](const std::filesystem::path& folder) {
        std::error_code error;
        return std::filesystem::is_directory(folder, error);
    });
}

} // namespace apcs
