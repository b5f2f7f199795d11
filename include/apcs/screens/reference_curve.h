#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/raster/graphics_screen.h"

#include <string>
#include <string_view>

namespace apcs {

// Compare (C, SPEC §3.1): the curve as it was when pinned, kept on the path screen beside the live
// one so that two settings are seen side by side.

// The reference's label, its staff values when pinned: "A: continuity -1.00" (the values that are
// not 0; "A: tension, continuity, bias 0" when none is), short enough for the boundary's top edge.
std::string reference_label(const StaffValues& staff);

// The reference's pixels dashed in its colour role (runs of 27 columns lit and 9 not: about three
// cells and one at 80x24, apart from the ghost's dots), its letter A on the curve where it lies a
// cell or more from the live curve `curve`, and `label` on the boundary's top edge.
void draw_reference(GraphicsScreen& screen, const Bitmap& reference, const Bitmap& curve, std::string_view label);

} // namespace apcs
