#pragma once

#include "apcs/animation/input_limits.h"
#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/formats/sif_export.h"

#include <filesystem>
#include <iosfwd>
#include <vector>

namespace apcs {

namespace limits {
// Synfig frames between two waypoints of `apcs export --sif`, and the document's frames per second.
inline constexpr Range sif_frames_per_span{1, 10000};
inline constexpr Range sif_fps{1, 1000};
} // namespace limits

// `apcs export FILE.dat --sif OUT.sif` (one path) or `apcs export KEY1 KEY2 PATH_FIRST PATH_LAST
// --sif OUT.sif` (the whole animation, as fit makes it): a Synfig document (SPEC §7.5).
struct ExportRequest {
    std::vector<std::filesystem::path> files; // one path file, or fit's four files
    std::filesystem::path sif;                // the document; "-" is standard output
    SifMotion motion = SifMotion::tcb;        // --sif-motion
    SifTiming timing;                         // --frames-per-span, --fps
};

ExitStatus run_export_command(const ExportRequest& request, const CommonOptions& options, std::ostream& out,
                              std::ostream& err);

// The view a document is seen along: the command line's when --view, --theta or --phi was given;
// else `top` for data whose z are all 0 (2-D data), else the session's default view.
ViewAngles export_view(const CommonOptions& options, bool all_z_zero);

} // namespace apcs
