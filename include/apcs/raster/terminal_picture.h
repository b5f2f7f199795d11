#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/bitmap.h"
#include "apcs/raster/pixel_picture.h"

#include <string>

namespace apcs {

// The two ways a terminal shows real pixels (SPEC §7.2.1): DEC sixel graphics (xterm -ti vt340,
// foot, WezTerm, mlterm, mintty) and the kitty graphics protocol (kitty, WezTerm, Ghostty, Konsole).
enum class TerminalPictureProtocol {
    sixel,
    kitty,
};

// The cells a terminal picture of the monitor's shape covers: 9x18-pixel cells, so that the
// 720x522 picture is 80 columns by 29 rows; kitty shows it on that many cells of whatever size its
// own are, a sixel terminal at its pixel size.
inline constexpr int terminal_picture_cell_width = 9;
inline constexpr int terminal_picture_cell_height = 18;

// The bitmap as the monitor showed it (PngShape::monitor: 720x348 becomes 720x522, each raster row
// 1.5 pixels tall), white on black, as the escape sequences that draw it in `protocol`, encoded by
// libchafa (no scaling, no dithering: every pixel is the PNG's), then a newline so that a `cat` of
// it leaves the prompt below the picture. Sixel: one DCS sequence, every pixel painted (black as a
// colour, not transparent). Kitty: `a=T,f=32` (RGBA) in base64 chunks, placed on 80x29 cells. A
// picture whose size is not a whole number of cells is scaled by libchafa to the cells that hold
// it. When libchafa fails, why ("libchafa: …").
Expected<std::string> encode_terminal_picture(const Bitmap& bitmap, TerminalPictureProtocol protocol);

// Cell rows `band` of `picture` (whole cells of `cell` screen pixels: scale_to_picture), lit pixels
// white and the others black, as the escape sequences that draw it at the cursor in `protocol`,
// unscaled, with no newline: sixel, one DCS sequence with every pixel of the band painted, white
// in colour register 0 and black in 1 in every band alike (a VT340 shares its registers among the
// pictures on the screen, so bands must not redefine each other's), as tall
// as the next multiple of 6 pixels (sixels are six rows: the rows below the band are left
// transparent); kitty, `a=T,f=32` placed on the band's cells. Why not, when libchafa fails or the
// band is not within the picture.
Expected<std::string> encode_picture_band(const Bitmap& picture, CellRowBand band, CellPixels cell,
                                          TerminalPictureProtocol protocol);

} // namespace apcs
