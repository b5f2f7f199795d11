#pragma once

#include "apcs/raster/cell_grid.h"
#include "apcs/screens/program_screen.h"

#include <string_view>

namespace apcs {

// A replay's caption (a ";;" comment of the script) on a row of its own, in reverse video, so that
// the message line (DS/DD, "control point 2 of 3", questions, errors) stays in view: in graphics
// mode on the key-hint row, in place of the hints; on the text console on the bottom row, the
// console scrolled up one row when that row is in use. An empty caption leaves the screen as it is.
ProgramScreen with_caption(ProgramScreen screen, std::string_view caption);

// The most columns the played-key badge takes; a longer TEXT line is cut, ending in "...".
inline constexpr int max_played_key_columns = 32;

// What a paced replay just played (step_label: "ENTER", "TEXT ani1.dat"), shown as screencast
// tools do: " key ENTER " in reverse video at the right end of the terminal's top row (the
// boundary's top line in graphics mode, the oldest console line in text mode), two columns from
// the edge; `place` follows it ("caption 2 of 7", SPEC §3.1), never cut, or stands alone where
// nothing has played yet (" caption 0 of 10 "). Neither, or a grid too narrow for the badge, leaves
// the grid as it is.
CellGrid with_played_key(CellGrid grid, std::string_view label, std::string_view place = {});

} // namespace apcs
