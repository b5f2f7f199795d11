#pragma once

#include "apcs/geometry/pixel_point.h"

#include <optional>
#include <vector>

namespace apcs {

// How a line is stroked, so that curves overlaid in one colour stay apart: solid, dashed
// (6 on, 4 off) or dotted (1 on, 2 off).
enum class LineStyle { solid, dashed, dotted };

// A drawn polyline kept as vector lines beside its pixels, so that a picture can be written at any
// scale (SVG). Points are raster pixels; one point is a single pixel. `clip` is the rectangle the
// raster was clipped to (right and bottom exclusive), if any besides the raster's own bounds.
struct Stroke {
    std::vector<PixelPoint> points;
    LineStyle style = LineStyle::solid;
    std::optional<PixelRect> clip;
    bool operator==(const Stroke&) const = default;
};

} // namespace apcs
