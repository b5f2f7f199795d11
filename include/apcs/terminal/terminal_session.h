#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/base/exit_status.h"
#include "apcs/input/interactive_program.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/pixel_picture.h"
#include "apcs/terminal/terminal.h"

namespace apcs {

// The screen of a terminal smaller than the graphics mode's least size: how large it must be.
CellGrid too_small_grid(TerminalSize size);

// `screen` in the cells of a terminal of `size`, or too_small_grid below the least size.
CellGrid graphics_grid(const GraphicsScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache);

// Runs `program` (a replay of the session, or apcs play's ScenePlayer) in the terminal: its
// screens in `glyphs` (already chosen: not GlyphSet::automatic) with their caption and badge laid
// on (replay_caption.h), the keys typed handed to it, its ticks every delay_ms() while it
// animates and its work while it is busy. Ctrl-L (Key::redraw) also repaints the whole terminal.
// Below the least size (text_screen_columns x short_screen_rows: 80x23, short_screen.h) the screen
// says how large it must be, and keys wait. Returns success when the program ended, stopped when stopped by a signal or a
// lost terminal, or why there is no usable terminal ("apcs: PROBLEM"). The terminal is given back
// on every way out, exceptions included. `colour` is the resolved --color (Terminal::open).
// `pixels` (--pixels, SPEC §7.2.1) asks the terminal once at the start (Terminal::detect_pixels):
// where it shows pictures, the graphics screens' drawing area is the raster itself as a picture
// (TerminalPixels), the other rows characters; where it does not, characters, with why on the
// caption row (when the screen has no caption) until a key is typed.
Expected<ExitStatus> run_terminal_program(InteractiveProgram& program, GlyphSet glyphs, ColourChoice colour,
                                          PixelChoice pixels);

} // namespace apcs
