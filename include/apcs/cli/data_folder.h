#pragma once

#include "apcs/base/diagnostic.h"

#include <filesystem>
#include <functional>

namespace apcs {

// What decides where `apcs figures` reads the bundled examples (n-to-l/, stick/, snake-apple/).
struct DataFolderClues {
    std::filesystem::path environment; // APCS_DATA; empty when unset or empty
    std::filesystem::path executable;  // this program's file, canonical; empty when unknown
    std::filesystem::path build_folder; // where the program was built, canonical
    std::filesystem::path source_data; // the source tree's data/
};

// The examples' folder, in this order: APCS_DATA when set (even if it is no folder: the user's
// choice is never overruled, and its problem is said); else PREFIX/share/apcs for a program in
// PREFIX/bin; else the source tree's data/, but only for a program inside its build folder, so
// that an installed copy never reads a source tree left behind. `is_folder` says which exist.
Expected<std::filesystem::path> choose_data_folder(const DataFolderClues& clues,
                                                   const std::function<bool(const std::filesystem::path&)>& is_folder);

// The clues of the running program: the environment, /proc/self/exe and the folders compiled in.
DataFolderClues running_program_clues();

// choose_data_folder with the running program's clues and the file system's folders.
Expected<std::filesystem::path> find_data_folder();

} // namespace apcs
