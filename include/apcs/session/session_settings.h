#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/memory_budget.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/surface_construction.h"
#include "apcs/screens/program_screen.h"

#include <cstdint>
#include <optional>
#include <string>

namespace apcs {

struct SessionSettings {
    int samples_per_segment = 32;
    int inbetween_count = 12;
    Spacing spacing = Spacing::nearest;
    SurfaceConstruction surface = SurfaceConstruction::blend; // --surface (SPEC §5.3)
    double step = 0.05; // staff step per key
    // What an empty answer takes where the command line gave it (--theta, --phi, --delay,
    // --slopes); else the thesis' example (30 40 200, 1 1).
    std::optional<double> theta_degrees;
    std::optional<double> phi_degrees;
    std::optional<int> delay_ms;
    // --delay given with --keys (SPEC §3.1): delay_ms replaces the delay every answer to the view
    // prompt gives, a script's "0 90 100" too, so a class can slow a lesson's animation down.
    bool delay_overrides_answer = false;
    std::optional<EndSlopes> slopes;
    // The staff values of path files with three columns (--tension, --continuity, --bias, --accel).
    StaffValues staff;
    // Where the overlay of all frames goes as a PNG when the animation ends, if anywhere: as the
    // monitor showed it (--png) and as the bare raster (--png-raw).
    std::optional<std::string> overlay_png;
    std::optional<std::string> overlay_png_raw;
    std::optional<std::string> overlay_svg; // the same as vector lines (--svg)
    // The memory one request may take (APCS_MEMORY_LIMIT): more points or samples are refused.
    std::uint64_t memory_limit_bytes = memory::default_limit_bytes;
    // The terminal draws a long path's first picture after a key and refines it while no key waits
    // (path_picture.h); scripts and tests take every key's work at once.
    Refinement refinement = Refinement::at_once;
    // False when nobody will see a screen of the session (apcs grade's replays): the path editor
    // then evaluates paths but draws no curve (PictureRefinement::seen).
    bool pictures_seen = true;
};

} // namespace apcs
