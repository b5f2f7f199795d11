#pragma once

namespace apcs {

// A position in raster pixels: origin top-left, x right, y down.
struct PixelPoint {
    int x = 0;
    int y = 0;
    friend constexpr bool operator==(const PixelPoint&, const PixelPoint&) = default;
};

// A rectangle in raster pixels; right and bottom are exclusive.
struct PixelRect {
    int left = 0;
    int top = 0;
    int right = 0;
    int bottom = 0;

    constexpr int width() const { return right - left; }
    constexpr int height() const { return bottom - top; }
    constexpr bool contains(PixelPoint point) const
    {
        return point.x >= left && point.x < right && point.y >= top && point.y < bottom;
    }
    friend constexpr bool operator==(const PixelRect&, const PixelRect&) = default;
};

} // namespace apcs
