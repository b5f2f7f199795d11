#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/base/exit_status.h"
#include "apcs/input/interactive_program.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/pixel_picture.h"

#include <functional>

namespace apcs {

// The terminal shell, supplied by the executable (the only part linked with ncurses): runs a
// program, the session's replay or apcs play's player, in its glyphs, --color and --pixels
// (run_terminal_program). Returns success or stopped, or why there is no usable terminal
// ("apcs: PROBLEM").
using TerminalRunner = std::function<Expected<ExitStatus>(InteractiveProgram& program, GlyphSet glyphs,
                                                          ColourChoice colour, PixelChoice pixels)>;

} // namespace apcs
