#pragma once

#include "apcs/geometry/pixel_point.h"
#include "apcs/raster/stroke.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace apcs {

// Liang–Barsky: clips the segment (x0, y0)–(x1, y1) to [x_low, x_high] × [y_low, y_high], bounds
// included; false when nothing of it is left.
inline bool clip_segment(double& x0, double& y0, double& x1, double& y1, double x_low, double y_low, double x_high,
                         double y_high)
{
    double enter = 0.0;
    double leave = 1.0;
    const double dx = x1 - x0;
    const double dy = y1 - y0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {x0 - x_low, x_high - x0, y0 - y_low, y_high - y0};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0)
                return false;
            continue;
        }
        const double r = q[i] / p[i];
        if (p[i] < 0.0)
            enter = std::max(enter, r);
        else
            leave = std::min(leave, r);
    }
    if (enter > leave)
        return false;
    const double start_x = x0 + enter * dx;
    const double start_y = y0 + enter * dy;
    x1 = x0 + leave * dx;
    y1 = y0 + leave * dy;
    x0 = start_x;
    y0 = start_y;
    return true;
}

// Calls plot(x, y) for each raster pixel of Bresenham's line from `from` to `to`, both ends
// included, that lies in `box` (right and bottom exclusive), in order from `from`. The line is
// clipped first, so that far-away ends cost nothing. The Painter's lines and the SVG's visible
// pieces both come from here, so that they light the same pixels.
template <typename Plot>
void each_line_pixel(PixelPoint from, PixelPoint to, PixelRect box, Plot plot)
{
    int x = from.x;
    int y = from.y;
    int end_x = to.x;
    int end_y = to.y;
    // A line inside the box needs no clipping (clipping would give back its own ends): a long
    // curve draws millions of short lines.
    if (!box.contains(from) || !box.contains(to)) {
        double x0 = from.x;
        double y0 = from.y;
        double x1 = to.x;
        double y1 = to.y;
        if (!clip_segment(x0, y0, x1, y1, box.left, box.top, box.right - 1, box.bottom - 1))
            return;
        x = static_cast<int>(std::lround(x0));
        y = static_cast<int>(std::lround(y0));
        end_x = static_cast<int>(std::lround(x1));
        end_y = static_cast<int>(std::lround(y1));
    }
    const int dx = std::abs(end_x - x);
    const int dy = -std::abs(end_y - y);
    const int step_x = x < end_x ? 1 : -1;
    const int step_y = y < end_y ? 1 : -1;
    int error = dx + dy;
    while (true) {
        plot(x, y);
        if (x == end_x && y == end_y)
            break;
        const int doubled = 2 * error;
        if (doubled >= dy) {
            error += dy;
            x += step_x;
        }
        if (doubled <= dx) {
            error += dx;
            y += step_y;
        }
    }
}

// Whether the pixel `phase` pixels along a styled polyline is lit: dashed 6 on, 4 off; dotted 1
// on, 2 off; solid always.
constexpr bool pattern_lit(LineStyle style, int phase)
{
    switch (style) {
    case LineStyle::solid: return true;
    case LineStyle::dashed: return phase % 10 < 6;
    case LineStyle::dotted: return phase % 3 == 0;
    }
    return true;
}

// Calls plot(x, y, lit) for each pixel of one segment of a styled polyline, as each_line_pixel
// walks it. A segment's first pixel is the previous segment's last, so it is counted once: skipped
// once `phase` (the pixels counted along the polyline so far, 0 at its start) is past 0. A segment
// that enters the box from outside starts at no pixel drawn: its first pixel in the box is drawn,
// whatever the polyline drew before (so that a curve drawn a block at a time draws the same).
template <typename Plot>
void each_styled_pixel(PixelPoint from, PixelPoint to, PixelRect box, LineStyle style, int& phase, Plot plot)
{
    bool first = true;
    each_line_pixel(from, to, box, [&](int x, int y) {
        const bool repeated = first && phase > 0 && PixelPoint{x, y} == from;
        first = false;
        if (repeated)
            return;
        plot(x, y, pattern_lit(style, phase));
        ++phase;
    });
}

} // namespace apcs
