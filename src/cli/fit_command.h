#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/animation/add_points.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/cli/options.h"

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <variant>

namespace apcs {

struct FitFiles {
    std::filesystem::path key1;
    std::filesystem::path key2;
    std::filesystem::path path_first;
    std::filesystem::path path_last;
};

// What fit reads: the keys given the same points (add_points.h), both paths' control points
// checked against them, and the settings each path is evaluated with (its file's SLOPES unless
// --slopes is given).
struct FitInputs {
    EqualisedKeys keys;
    ControlPoints first;
    ControlPoints last;
    PathSettings first_settings;
    PathSettings last_settings;
};

// Reads and checks fit's four files; a problem is reported on `err` and its exit status returned.
std::variant<FitInputs, ExitStatus> read_fit_inputs(const FitFiles& files, const CommonOptions& options,
                                                    std::ostream& err);

struct FittedAnimation {
    EqualisedKeys keys;
    FrameSequence frames; // KEY1, the in-betweens, KEY2
};

// fit's whole work for a command that needs every frame at once (--print, the pictures, export):
// the inputs, the memory budget (with `more_bytes_per_frame_point` for what the caller makes of
// every point of every frame: export's document), the paths, then the frames.
std::variant<FittedAnimation, ExitStatus> fit_all_frames(const FitFiles& files, const CommonOptions& options,
                                                         std::ostream& err, std::uint64_t more_bytes_per_frame_point = 0);

// `apcs fit KEY1 KEY2 PATH_FIRST PATH_LAST`: equalise the keys, check and evaluate both paths,
// fit the surface, then print the frames (--print) or write inb001.dat … into --out.
ExitStatus run_fit_command(const FitFiles& files, const CommonOptions& options, std::ostream& out, std::ostream& err);

} // namespace apcs
