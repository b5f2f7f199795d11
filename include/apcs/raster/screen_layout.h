#pragma once

#include "apcs/geometry/hercules.h"
#include "apcs/geometry/pixel_point.h"

namespace apcs::layout {

// The graphics screen of the session, in raster pixels and 80x24 text cells. The drawing area and
// its boundary (thesis Make_Boundary) fill text rows 0–17; row 18 holds the prompt or message,
// rows 19–22 the four-line staff (fig. 3.1.5), row 23 the keys.
// The boundary's bottom line stays two pixels above row 18 so that, mapped to 24 character rows,
// it lands in row 17 and not under the message.
inline constexpr PixelRect drawing_area{0, 0, hercules::screen_width, hercules::text_row_top(18) - 2};
// Where fitted views place what they show: one text cell inside the boundary on every side, so no
// control point or key frame lands on the frame line (SPEC §7.1).
inline constexpr PixelRect view_area{drawing_area.left + hercules::cell_width,
                                     drawing_area.top + hercules::text_row_top(1),
                                     drawing_area.right - hercules::cell_width,
                                     drawing_area.bottom - hercules::text_row_top(1)};
// What curves are clipped to: inside the boundary, so a slack curve never runs over the message
// and staff rows.
inline constexpr PixelRect inside_boundary{drawing_area.left + 1, drawing_area.top + 1, drawing_area.right - 1,
                                           drawing_area.bottom - 1};
inline constexpr int message_row = 18;
inline constexpr int first_staff_row = 19;
inline constexpr int key_help_row = 23;

// A staff line runs from −1 at staff_left to +1 at staff_right, through the middle of its row.
inline constexpr int staff_label_column = 1;
inline constexpr int staff_left = 15 * hercules::cell_width;
inline constexpr int staff_right = 66 * hercules::cell_width;
inline constexpr int staff_value_column = 69;
inline constexpr int staff_tick_half_height = 3;
inline constexpr int staff_marker_half_height = 4;

constexpr int staff_line_y(int line) { return hercules::text_row_top(first_staff_row + line) + hercules::cell_height / 2; }
constexpr int staff_x(double value) { return staff_left + static_cast<int>((value + 1.0) / 2.0 * (staff_right - staff_left) + 0.5); }

} // namespace apcs::layout
