#pragma once

#include "apcs/base/utf8.h"

#include "apcs/geometry/pixel_point.h"
#include "apcs/raster/bitmap.h"
#include "apcs/raster/stroke.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// How a primitive changes the pixels it covers. `toggle` (XOR) draws a moving cursor that the same
// call erases again; every pixel of one primitive is toggled once, however often its strokes cross.
enum class DrawMode { set, clear, toggle };

// Draws into a Bitmap it does not own. Lines and pixels are clipped to the bitmap, and to `clip`
// when one is given (right and bottom exclusive); markers and text to the bitmap only.
class Painter {
public:
    explicit Painter(Bitmap& target) : m_target(target) {}
    Painter(Bitmap& target, PixelRect clip) : m_target(target), m_clip(clip) {}

    // From now on lines and pixels drawn in DrawMode::set are also kept in `strokes` as vector
    // lines (a segment that starts where the last stroke ended, in its style, extends it).
    // Markers, text and toggled or cleared pixels are not kept: pictures draw marks and text from
    // the GraphicsScreen's own lists.
    Painter& record_into(std::vector<Stroke>& strokes);

    void pixel(PixelPoint point, DrawMode mode = DrawMode::set);
    // Bresenham's line from `from` to `to`, both ends included, clipped to the bitmap first so
    // that far-away ends cost nothing.
    void line(PixelPoint from, PixelPoint to, DrawMode mode = DrawMode::set);
    // A styled line; `phase` counts pixels along a polyline so the pattern runs on across its
    // segments (start it at 0).
    void styled_line(PixelPoint from, PixelPoint to, LineStyle style, int& phase);
    // A control point's mark: an `x` of 5x5 pixels centred on `centre`.
    void cross_marker(PixelPoint centre, DrawMode mode = DrawMode::set);
    // A small filled square of 3x3 pixels, for the shown in-between positions.
    void dot_marker(PixelPoint centre, DrawMode mode = DrawMode::set);
    // The local-control arrow: its tip at `tip`, pointing up and left, 9 pixels long.
    void arrow(PixelPoint tip, DrawMode mode = DrawMode::toggle);
    void rectangle(PixelRect rect, DrawMode mode = DrawMode::set);
    // UTF-8 text in 9x14 cells, the first cell's top-left corner at `top_left`.
    void text(PixelPoint top_left, std::string_view utf8, DrawMode mode = DrawMode::set);

    // Where it draws: the clip on the bitmap, or the whole bitmap.
    PixelRect bounds() const;

private:
    void record(PixelPoint from, PixelPoint to, LineStyle style);

    Bitmap& m_target;
    std::optional<PixelRect> m_clip;
    std::vector<Stroke>* m_record = nullptr;
};

} // namespace apcs
