#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"

#include <filesystem>
#include <iosfwd>

namespace apcs {

struct FitFiles {
    std::filesystem::path key1;
    std::filesystem::path key2;
    std::filesystem::path path_first;
    std::filesystem::path path_last;
};

// `apcs fit KEY1 KEY2 PATH_FIRST PATH_LAST`: equalise the keys, check and evaluate both paths,
// fit the surface, then print the frames (--print) or write inb001.dat … into --out.
ExitStatus run_fit_command(const FitFiles& files, const CommonOptions& options, std::ostream& out, std::ostream& err);

} // namespace apcs
