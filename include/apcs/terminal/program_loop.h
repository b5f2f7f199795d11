#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/input/interactive_program.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/terminal/terminal_device.h"
#include "apcs/terminal/terminal_pixels.h"

namespace apcs {

// The screen of a terminal smaller than the graphics mode's least size: how large it must be.
CellGrid too_small_grid(TerminalSize size);

// `screen` in the cells of a terminal of `size`, or too_small_grid below the least size.
CellGrid graphics_grid(const GraphicsScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache);

// The one terminal loop (run_terminal_program opens the terminal and runs it): `program`'s
// screens in `glyphs` with their caption and badge laid on (replay_caption.h), painted on
// `terminal` when the program's screen revision or the terminal changed, but not while keys that
// came together are still being read (a paste, a held key, a terminal's flood) unless the screen
// went unpainted for a tenth of a second by the terminal's clock; the keys typed handed to the
// program, its ticks every delay_ms() while it animates and its work, in slices of 30 ms, while it
// is busy. Ctrl-L (Key::redraw) also repaints the whole terminal. Below the least size
// (text_screen_columns x short_screen_rows: 80x23, short_screen.h) the screen says how large it
// must be, and keys wait. Where `pixels` shows pictures, the graphics screens' drawing area is the
// raster as a picture, the other rows characters; where it does not, why goes on the caption row
// (when the screen has no caption) until a key is typed. Returns success when the program ended,
// stopped when the terminal said stop (a signal, the terminal lost).
ExitStatus run_program_on(InteractiveProgram& program, TerminalDevice& terminal, TerminalPixels& pixels,
                          GlyphSet glyphs);

} // namespace apcs
