#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/surface_construction.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/formats/key_event.h"
#include "apcs/lesson/replay_pace.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace apcs {

// Which of the session's answers the command line gave: an empty answer at the session's prompt
// takes these where given, else the thesis' example (SPEC §3). A scene's VIEW and SPACING lines
// give way to them too (SPEC §8.1).
struct GivenOptions {
    bool theta = false;   // --theta
    bool phi = false;     // --phi
    bool delay = false;   // --delay
    bool slopes = false;  // --slopes
    bool spacing = false; // --spacing
    // Of the options a key script may carry (script_options.h), those given, by name ("--step"),
    // on the command line or by the script's OPTIONS line; --view gives --theta and --phi.
    std::vector<std::string> carried;
};

// The options every command shares (SPEC §1), validated by the command line parser.
struct CommonOptions {
    StaffValues staff;
    PathSettings path;
    SurfaceConstruction surface = SurfaceConstruction::blend; // --surface (SPEC §5.3)
    ViewAngles view;
    int delay_ms = 200;
    std::filesystem::path workdir;
    GlyphSet glyphs = GlyphSet::automatic;
    ColourChoice colour = ColourChoice::automatic; // --color (SPEC §7.2.1)
    PixelChoice pixels = PixelChoice::off;          // --pixels (SPEC §7.2.1)
    double step = 0.05;
    std::optional<std::filesystem::path> keys;
    std::optional<std::filesystem::path> record;
    ReplayPace pace; // --pace: how a --keys replay plays on a terminal
    std::optional<std::filesystem::path> handout; // --handout: each caption's screen, as PNG and text
    bool paper = false;                           // --paper: the handout's pictures black on white
    std::optional<std::filesystem::path> png;     // as the monitor showed it, 720x522
    std::optional<std::filesystem::path> png_raw; // the bare 720x348 raster
    std::optional<std::filesystem::path> svg;     // the same drawing as vector lines
    std::optional<std::filesystem::path> gif;     // the frames, animated (fit, inbetween)
    std::optional<std::filesystem::path> sixel;   // as --png, in sixel escape sequences
    std::optional<std::filesystem::path> kitty;   // as --png, in the kitty graphics protocol
    bool print = false;
    std::optional<std::filesystem::path> out;
    GivenOptions given;
    // The memory budget of one request (memory_budget.h); unset, APCS_MEMORY_LIMIT or the default.
    std::optional<std::uint64_t> memory_limit;
    // The files the run reads: the command's own (set by the command line, not an option) and a
    // scene's SHAPE and KEYS files (added by play). No output, picture or backup replaces one.
    std::vector<std::filesystem::path> read_files;
};

// Whether a still picture was asked for (--png, --png-raw, --svg, --sixel or --kitty).
inline bool still_pictures_asked(const CommonOptions& options)
{
    return options.png || options.png_raw || options.svg || options.sixel || options.kitty;
}

// Whether a picture was asked for (a still one or --gif).
inline bool pictures_asked(const CommonOptions& options) { return still_pictures_asked(options) || options.gif; }

} // namespace apcs
