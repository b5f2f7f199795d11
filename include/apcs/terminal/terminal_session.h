#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/session/exit_status.h"
#include "apcs/session/key_event.h"
#include "apcs/session/interactive_program.h"
#include "apcs/session/replay_hooks.h"
#include "apcs/terminal/terminal.h"

#include <memory>
#include <vector>

namespace apcs {

// The screen of a terminal smaller than the graphics mode's least size: how large it must be.
CellGrid too_small_grid(TerminalSize size);

// `screen` in the cells of a terminal of `size`, or too_small_grid below the least size.
CellGrid graphics_grid(const GraphicsScreen& screen, TerminalSize size, GlyphSet glyphs, AsciiGlyphCache& cache);

// Runs `program` (the session, or apcs play's ScenePlayer) in the terminal: the script's keys
// first, as if typed, at `pace` (at once; one step every N ms; one step per Space: a step is a key
// or a whole TEXT line) with its captions on the key-hint row (replay_caption.h) and, when paced,
// the step just played at the top right, then the keyboard, the graphics screen in `glyphs` (already chosen: not
// GlyphSet::automatic). Every key handled is appended to `recorded`; Ctrl-L (Key::redraw) also
// repaints the whole terminal. Below the least size (text_screen_columns x text_screen_rows) the
// screen says how large it must be, and keys wait. While a paced replay plays, Esc ends it (the
// keyboard takes over) and other keys are ignored. Returns success when the program ended,
// stopped when stopped by a signal or a lost terminal, or why there is no usable terminal
// ("apcs: PROBLEM"). The terminal is given back on every way out, exceptions included. `hooks`
// hear of each caption reached (replay_hooks.h), until Esc ends the replay; `colour` is the resolved
// --color (Terminal::open). `pixels` (--pixels, SPEC §7.2.1) asks the terminal once at the start
// (Terminal::detect_pixels): where it shows pictures, the graphics screens' drawing area is the raster
// itself as a picture (TerminalPixels), the other rows characters; where it does not, characters, with
// why on the caption row until a key is typed.
Expected<ExitStatus> run_terminal_session(InteractiveProgram& program, const KeyScript& script, ReplayPace pace,
                                          GlyphSet glyphs, ColourChoice colour, PixelChoice pixels,
                                          std::vector<KeyEvent>& recorded, const ReplayHooks& hooks = {});

} // namespace apcs
