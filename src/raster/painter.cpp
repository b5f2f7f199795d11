#include "apcs/raster/painter.h"

#include "apcs/raster/font.h"
#include "apcs/raster/line_pixels.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

namespace apcs {

namespace {

void apply(Bitmap& target, int x, int y, DrawMode mode)
{
    switch (mode) {
    case DrawMode::set:
        target.set(x, y, true);
        break;
    case DrawMode::clear:
        target.set(x, y, false);
        break;
    case DrawMode::toggle:
        target.toggle(x, y);
        break;
    }
}

void toggle_once(Bitmap& target, std::vector<PixelPoint>& pixels)
{
    std::sort(pixels.begin(), pixels.end(), [](PixelPoint a, PixelPoint b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
    for (const PixelPoint point : pixels)
        target.toggle(point.x, point.y);
}

bool same_clip(const std::optional<PixelRect>& a, const std::optional<PixelRect>& b)
{
    if (!a || !b)
        return a.has_value() == b.has_value();
    return a->left == b->left && a->top == b->top && a->right == b->right && a->bottom == b->bottom;
}

} // namespace

PixelRect Painter::bounds() const
{
    const PixelRect whole{0, 0, m_target.width(), m_target.height()};
    if (!m_clip)
        return whole;
    return {std::max(whole.left, m_clip->left), std::max(whole.top, m_clip->top), std::min(whole.right, m_clip->right),
            std::min(whole.bottom, m_clip->bottom)};
}

Painter& Painter::record_into(std::vector<Stroke>& strokes)
{
    m_record = &strokes;
    return *this;
}

void Painter::record(PixelPoint from, PixelPoint to, LineStyle style)
{
    if (m_record == nullptr)
        return;
    if (!m_record->empty()) {
        Stroke& last = m_record->back();
        if (last.style == style && same_clip(last.clip, m_clip) && last.points.size() > 1 && last.points.back() == from) {
            last.points.push_back(to);
            return;
        }
    }
    Stroke stroke{{from}, style, m_clip};
    if (to != from)
        stroke.points.push_back(to);
    m_record->push_back(std::move(stroke));
}

void Painter::pixel(PixelPoint point, DrawMode mode)
{
    if (mode == DrawMode::set)
        record(point, point, LineStyle::solid);
    const PixelRect box = bounds();
    if (point.x >= box.left && point.x < box.right && point.y >= box.top && point.y < box.bottom)
        apply(m_target, point.x, point.y, mode);
}

void Painter::line(PixelPoint from, PixelPoint to, DrawMode mode)
{
    if (mode == DrawMode::set)
        record(from, to, LineStyle::solid);
    each_line_pixel(from, to, bounds(), [&](int x, int y) { apply(m_target, x, y, mode); });
}

void Painter::styled_line(PixelPoint from, PixelPoint to, LineStyle style, int& phase)
{
    record(from, to, style);
    each_styled_pixel(from, to, bounds(), style, phase, [&](int x, int y, bool lit) {
        if (lit)
            m_target.set(x, y, true);
    });
}

void Painter::cross_marker(PixelPoint centre, DrawMode mode)
{
    std::vector<PixelPoint> pixels;
    for (int d = -2; d <= 2; ++d) {
        pixels.push_back({centre.x + d, centre.y + d});
        pixels.push_back({centre.x + d, centre.y - d});
    }
    if (mode == DrawMode::toggle)
        return toggle_once(m_target, pixels);
    for (const PixelPoint point : pixels)
        apply(m_target, point.x, point.y, mode);
}

void Painter::dot_marker(PixelPoint centre, DrawMode mode)
{
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            apply(m_target, centre.x + dx, centre.y + dy, mode);
}

void Painter::arrow(PixelPoint tip, DrawMode mode)
{
    std::vector<PixelPoint> pixels;
    const auto collect = [&](PixelPoint from, PixelPoint to) {
        each_line_pixel(from, to, bounds(), [&](int x, int y) { pixels.push_back({x, y}); });
    };
    collect(tip, {tip.x + 8, tip.y + 8});
    collect(tip, {tip.x + 4, tip.y});
    collect(tip, {tip.x, tip.y + 4});
    if (mode == DrawMode::toggle)
        return toggle_once(m_target, pixels);
    for (const PixelPoint point : pixels)
        apply(m_target, point.x, point.y, mode);
}

void Painter::rectangle(PixelRect rect, DrawMode mode)
{
    const int right = rect.right - 1;
    const int bottom = rect.bottom - 1;
    line({rect.left, rect.top}, {right, rect.top}, mode);
    line({rect.left, bottom}, {right, bottom}, mode);
    if (bottom - rect.top > 1) {
        line({rect.left, rect.top + 1}, {rect.left, bottom - 1}, mode);
        line({right, rect.top + 1}, {right, bottom - 1}, mode);
    }
}

void Painter::text(PixelPoint top_left, std::string_view utf8, DrawMode mode)
{
    int left = top_left.x;
    for (const char32_t code_point : decode_utf8(utf8)) {
        // A combining mark takes no cell on a terminal, so none here either: the font has no
        // marks to lay over a letter, and a '?' cell for each would push the rest of the line
        // out of its columns.
        if (cell_width(code_point) == 0)
            continue;
        for (int row = 0; row < Font::cell_height; ++row)
            for (int column = 0; column < Font::cell_width; ++column)
                if (Font::pixel(code_point, column, row))
                    apply(m_target, left + column, top_left.y + row, mode);
        left += Font::cell_width;
    }
}

} // namespace apcs
