#pragma once

namespace apcs::hercules {

// The Hercules Graphics Card's 720x348 monochrome mode, the screen of the 1989 APCS.
inline constexpr int screen_width = 720;
inline constexpr int screen_height = 348;
// Text cells of the 9x14 font: 80 columns by 24 full rows (24·14 = 336 pixels).
inline constexpr int cell_width = 9;
inline constexpr int cell_height = 14;
inline constexpr int text_columns = screen_width / cell_width;
inline constexpr int text_rows = screen_height / cell_height;
// Graphics mode's text rows (staff labels, prompts) spread over the whole raster, 14.5 pixels
// apart, so that each of an 80x24 terminal's rows holds exactly one: the top pixel row of text row
// `row` (0 … 23).
constexpr int text_row_top(int row) { return row * screen_height / text_rows; }
// Horizontal scale factor of the device mapping (thesis Ch. 2.3): Hercules pixels are about 1.5
// times as tall as wide, so x is stretched to keep a square square.
inline constexpr double aspect_correction = 1.5;

} // namespace apcs::hercules
