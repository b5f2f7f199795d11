#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/base/exit_status.h"
#include "apcs/input/interactive_program.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/terminal/program_loop.h"

namespace apcs {

// Runs `program` (a replay of the session, or apcs play's ScenePlayer) in the terminal, the one
// loop of run_program_on on the real terminal (Terminal), its screens in `glyphs` (already
// chosen: not GlyphSet::automatic). Returns success when the program ended, stopped when stopped
// by a signal or a lost terminal, or why there is no usable terminal ("apcs: PROBLEM"). The
// terminal is given back on every way out, exceptions included. `colour` is the resolved --color
// (Terminal::open). `pixels` (--pixels, SPEC §7.2.1) asks the terminal once at the start
// (Terminal::detect_pixels).
Expected<ExitStatus> run_terminal_program(InteractiveProgram& program, GlyphSet glyphs, ColourChoice colour,
                                          PixelChoice pixels);

} // namespace apcs
