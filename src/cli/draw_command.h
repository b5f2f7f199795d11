#pragma once

#include "apcs/animation/graphic.h"
#include "apcs/animation/view_transform.h"
#include "apcs/cli/options.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/base/exit_status.h"

#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// One graphic of a drawing and the name its legend gives it.
struct NamedGraphic {
    std::string name;
    Graphic graphic;
};

// "solid: key1.dat  dashed: key2.dat  dotted: 12 between" (one name where one graphic is between):
// the strokes of overlay_style (session/frames_overlay.h).
std::string overlay_legend(std::span<const NamedGraphic> graphics);

// The graphics overlaid in one view fitted to them all, each part a polyline (the pen lifted
// between parts), in the styles of overlay_style, the legend on the message line; the lines are
// recorded as strokes too (for SVG).
GraphicsScreen draw_graphics_overlay(std::span<const NamedGraphic> graphics, ViewAngles angles);

// `apcs draw FILE…`: reads every file (key frames or in-between files, .dat) and writes the
// overlay to the pictures --png, --png-raw and --svg name.
ExitStatus run_draw_command(std::span<const std::filesystem::path> files, const CommonOptions& options,
                            std::ostream& out, std::ostream& err);

} // namespace apcs
