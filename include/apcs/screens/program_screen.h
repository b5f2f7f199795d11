#pragma once

#include "apcs/raster/cell_grid.h"
#include "apcs/raster/graphics_screen.h"

#include <string>

namespace apcs {

// What an interactive program (a replay of the session, apcs play) shows now: the DOS text console
// or the graphics screen, and what a replay lays over it where it is shown (replay_caption.h): its
// caption on a row of its own, and the step it just played at the top right.
struct ProgramScreen {
    bool graphics = false;
    CellGrid text;          // 80x24, when !graphics
    GraphicsScreen picture; // when graphics
    std::string caption = {};
    std::string badge = {};
    std::string badge_place = {}; // beside the badge: "caption 2 of 7"
    bool operator==(const ProgramScreen&) const = default;
};

} // namespace apcs
