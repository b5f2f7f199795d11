#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace apcs {

// One view of a bundled example of thesis Ch. 5, drawn with all its frames overlaid.
struct ExampleFigure {
    std::string folder;     // under the data folder
    std::string path_first; // path files, as shipped
    std::string path_last;
    ViewAngles view;
    std::string file_name;
    std::string title;
    // An object of the example that stands still, drawn once (empty: none).
    std::string still_file = {};
};

const std::vector<ExampleFigure>& example_figures();

// `apcs figures --out DIR`: fig-3-1-1.png … fig-3-1-4.png, one PNG per example view,
// fig-3-2-1.png (the thesis' surface fitting, its pair built in), example-1-n-to-l-surfaces.png
// (both surfaces side by side) and fig-3-3-3.png; the examples read from --workdir, else from
// data_folder.
ExitStatus run_figures_command(const CommonOptions& options, const std::filesystem::path& data_folder,
                               std::ostream& out, std::ostream& err);

// The same with the examples of --workdir, else of the data folder (data_folder.h); a data folder
// that cannot be found is said before any figure is written.
ExitStatus run_figures_command(const CommonOptions& options, std::ostream& out, std::ostream& err);

} // namespace apcs
