#include "apcs/screens/path_overlays.h"

#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/speed_law.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/path_screen.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace apcs {

namespace {

PixelPoint rounded(double x, double y) { return DevicePoint{x, y}.rounded(); }

// A head of two strokes, 6 pixels long, 25 degrees either side of the shaft.
void arrow_head(Painter& painter, DevicePoint tail, DevicePoint tip)
{
    const double length = std::hypot(tip.x - tail.x, tip.y - tail.y);
    if (length < 1.0)
        return;
    const double back_x = (tail.x - tip.x) / length;
    const double back_y = (tail.y - tip.y) / length;
    constexpr double head = 6.0;
    const double cos_a = std::cos(0.436);
    const double sin_a = std::sin(0.436);
    for (const double side : {1.0, -1.0}) {
        const double x = back_x * cos_a - side * back_y * sin_a;
        const double y = side * back_x * sin_a + back_y * cos_a;
        painter.line(tip.rounded(), rounded(tip.x + head * x, tip.y + head * y));
    }
}

// The part of a segment inside a rectangle; `inside` false when it misses it.
struct ClippedSegment {
    DevicePoint tail;
    DevicePoint tip;
    bool inside = false;
};

// The part of the segment from `tail` to `tip` inside `area` (Liang-Barsky).
ClippedSegment clipped(DevicePoint tail, DevicePoint tip, const PixelRect& area)
{
    const double dx = tip.x - tail.x;
    const double dy = tip.y - tail.y;
    double enter = 0.0;
    double leave = 1.0;
    const std::pair<double, double> sides[] = {{-dx, tail.x - area.left},
                                               {dx, area.right - 1 - tail.x},
                                               {-dy, tail.y - area.top},
                                               {dy, area.bottom - 1 - tail.y}};
    for (const auto& [towards, room] : sides) {
        if (towards == 0.0) {
            if (room < 0.0)
                return {};
            continue;
        }
        const double at = room / towards;
        if (towards < 0.0)
            enter = std::max(enter, at);
        else
            leave = std::min(leave, at);
    }
    if (enter > leave)
        return {};
    return {{tail.x + enter * dx, tail.y + enter * dy}, {tail.x + leave * dx, tail.y + leave * dy}, true};
}

void world_arrow(GraphicsScreen& screen, Painter& painter, const ViewTransform& view, const Vec3& from, const Vec3& to,
                 LineStyle style)
{
    const DevicePoint tail = view.to_device(from);
    const DevicePoint tip = view.to_device(to);
    int phase = 0;
    painter.styled_line(tail.rounded(), tip.rounded(), style, phase);
    arrow_head(painter, tail, tip);
    // On a terminal the part inside the view area, so that its characters never land on the boundary.
    const ClippedSegment shown = clipped(tail, tip, layout::view_area);
    if (shown.inside)
        screen.arrows.push_back({shown.tail.rounded(), shown.tip.rounded(), style, ColourRole::tangent});
}

std::string vector_text(const Vec3& vector)
{
    return format_two_decimals(vector.x) + " " + format_two_decimals(vector.y) + " " + format_two_decimals(vector.z);
}

} // namespace

void draw_tangent_arrows(GraphicsScreen& screen, Painter& painter, std::span<const HermiteSegment> segments,
                         const ViewTransform& view, double scale)
{
    for (std::size_t point = 0; point <= segments.size() && !segments.empty(); ++point) {
        const Vec3 at = point < segments.size() ? segments[point].start : segments.back().end;
        const PointTangents tangents = tangents_at(segments, point);
        if (tangents.outgoing) {
            const Vec3 tip = at + scale * *tangents.outgoing;
            world_arrow(screen, painter, view, at, tip, LineStyle::solid);
            screen.marks.push_back({view.to_device(tip).rounded(), MarkKind::tangent_end, CellStyle::plain, ColourRole::tangent});
        }
        if (tangents.incoming) {
            const Vec3 tail = at - scale * *tangents.incoming;
            world_arrow(screen, painter, view, tail, at, LineStyle::dashed);
            screen.marks.push_back({view.to_device(tail).rounded(), MarkKind::tangent_end, CellStyle::plain, ColourRole::tangent});
        }
    }
}

double tangent_arrow_scale(std::span<const ControlPoint> points, const ViewTransform& view)
{
    constexpr double true_length = 1.0;
    // A mean chord shorter than nine cells leaves arrows a back row cannot compare.
    constexpr double shortest_readable_pixels = 9.0 * hercules::cell_width;
    double chord_pixels = 0.0;
    for (std::size_t k = 1; k < points.size(); ++k) {
        const DevicePoint a = view.to_device(points[k - 1].position);
        const DevicePoint b = view.to_device(points[k].position);
        chord_pixels += std::hypot(b.x - a.x, b.y - a.y);
    }
    if (points.size() < 2 || !(chord_pixels > 0.0))
        return true_length;
    const double mean_chord = chord_pixels / static_cast<double>(points.size() - 1);
    // Lengthened three times at most, as a third of the tangent once was: arrows of a picture
    // crowded into a few cells stay near it, not thousands of pixels long.
    constexpr double most_lengthened = 3.0;
    return mean_chord >= shortest_readable_pixels ? true_length
                                                  : std::min(most_lengthened, shortest_readable_pixels / mean_chord);
}

std::string tangent_numbers(std::span<const HermiteSegment> segments, std::size_t point)
{
    const PointTangents tangents = tangents_at(segments, point);
    std::string text = "point " + std::to_string(point + 1);
    text += tangents.incoming ? "  DS " + vector_text(*tangents.incoming) : "  no DS (first point)";
    text += tangents.outgoing ? "  DD " + vector_text(*tangents.outgoing) : "  no DD (last point)";
    return text;
}

std::optional<std::size_t> span_of_point(const EvaluatedPath& path, std::size_t point)
{
    const auto& spans = path.span_timings;
    for (std::size_t s = 0; s < spans.size(); ++s)
        if (point < spans[s].span.last_point)
            return s;
    return spans.empty() ? std::nullopt : std::optional<std::size_t>(spans.size() - 1);
}

std::vector<LawTick> law_ticks(const EvaluatedPath& path, std::size_t span)
{
    std::vector<LawTick> ticks;
    if (span >= path.span_timings.size())
        return ticks;
    const SpanTiming& timing = path.span_timings[span];
    const double frames = static_cast<double>(timing.inbetween_count + 1);
    for (std::size_t j = 0; j < timing.inbetween_count; ++j) {
        const Inbetween& inbetween = path.inbetweens[timing.first_inbetween + j];
        const double distance = timing.length_fraction > 0.0
            ? (inbetween.arc_fraction - timing.start_fraction) / timing.length_fraction
            : 0.0;
        ticks.push_back({static_cast<double>(j + 1) / frames, std::clamp(distance, 0.0, 1.0)});
    }
    return ticks;
}

namespace {

constexpr int inset_columns = 24;
constexpr int inset_rows = 8;

// The inset whose box starts in text row `row` at text column `column`: its box (the title on its
// top edge, "frame" on its bottom edge), the axis names' cells and the plot (from the row under
// "distance" to the row above the bottom edge, right of the distance ticks' column).
struct LawInset {
    PixelRect box;
    int title_row = 0;
    int title_column = 0;
    PixelRect plot;
};

LawInset inset_at(int row, int column)
{
    const int left = column * hercules::cell_width;
    const PixelRect box{left, hercules::text_row_top(row) + 1, left + inset_columns * hercules::cell_width - 1,
                        hercules::text_row_top(row + inset_rows) - 1};
    const PixelRect plot{left + 2 * hercules::cell_width + hercules::cell_width / 2, hercules::text_row_top(row + 2) + 3,
                         box.right - hercules::cell_width, hercules::text_row_top(row + inset_rows - 1) - 3};
    return {box, row, column + 1, plot};
}

// The text row a raster pixel row lies in.
int text_row_of(int y) { return y * hercules::text_rows / hercules::screen_height; }

// Top rows 1-8 or 9-16, columns 1-24 or 55-78: inside the boundary, clear of the message line.
std::vector<LawInset> insets()
{
    constexpr int right_column = hercules::text_columns - 1 - inset_columns;
    return {inset_at(1, right_column), inset_at(1, 1), inset_at(9, right_column), inset_at(9, 1)};
}

PixelPoint plot_point(const PixelRect& plot, double frame_fraction, double distance_fraction)
{
    return rounded(plot.left + frame_fraction * (plot.right - plot.left),
                   plot.bottom - distance_fraction * (plot.bottom - plot.top));
}

// What an inset would hide: control points, then in-between marks, then lit pixels.
std::tuple<std::size_t, std::size_t, std::size_t> hidden_by(const GraphicsScreen& screen, const PixelRect& box)
{
    std::size_t control_points = 0;
    std::size_t marks = 0;
    for (const PixelMark& mark : screen.marks)
        if (box.contains(mark.at))
            ++(mark.kind == MarkKind::control_point ? control_points : marks);
    std::size_t lit = 0;
    for (int y = box.top; y < box.bottom; ++y)
        for (int x = box.left; x < box.right; ++x)
            lit += screen.bitmap.get(x, y) ? 1u : 0u;
    return {control_points, marks, lit};
}

void clear_box(GraphicsScreen& screen, const PixelRect& box)
{
    for (int y = box.top; y < box.bottom; ++y)
        for (int x = box.left; x < box.right; ++x)
            screen.bitmap.set(x, y, false);
    std::erase_if(screen.marks, [&](const PixelMark& mark) { return box.contains(mark.at); });
    std::erase_if(screen.arrows, [&](const CellArrow& arrow) { return box.contains(arrow.tail) || box.contains(arrow.tip); });
}

std::string inset_title(const SpanTiming& timing, std::size_t span, std::size_t span_count)
{
    std::string text = "law a " + format_staff_value(timing.span.acceleration);
    if (span_count > 1)
        text += "  span " + std::to_string(span + 1) + "/" + std::to_string(span_count);
    return text;
}

void draw_law(GraphicsScreen& screen, const LawInset& inset, const EvaluatedPath& path, std::size_t span)
{
    const SpanTiming& timing = path.span_timings[span];
    Bitmap layer;
    Painter painter(layer, {inset.box.left, inset.box.top, inset.box.right + 1, inset.box.bottom + 1});
    painter.rectangle(inset.box);
    const PixelRect& plot = inset.plot;
    painter.line(plot_point(plot, 0, 0), plot_point(plot, 1, 0));
    painter.line(plot_point(plot, 0, 0), plot_point(plot, 0, 1));
    constexpr int curve_pieces = 48;
    for (int i = 1; i <= curve_pieces; ++i) {
        const double from = static_cast<double>(i - 1) / curve_pieces;
        const double to = static_cast<double>(i) / curve_pieces;
        painter.line(plot_point(plot, from, acceleration_distance_fraction(from, timing.span.acceleration)),
                     plot_point(plot, to, acceleration_distance_fraction(to, timing.span.acceleration)));
    }
    // The distances as ticks: a '-' left of the distance axis in each text row one falls in, so
    // that they read as ticks at any size (drawn as pixels, they merged with the box and the axis).
    std::vector<int> tick_rows;
    for (const LawTick& tick : law_ticks(path, span)) {
        screen.marks.push_back({plot_point(plot, tick.frame_fraction, tick.distance_fraction), MarkKind::inbetween,
                                CellStyle::plain, ColourRole::law});
        const int row = text_row_of(plot_point(plot, 0, tick.distance_fraction).y);
        if (std::find(tick_rows.begin(), tick_rows.end(), row) == tick_rows.end())
            tick_rows.push_back(row);
    }
    paint_layer(screen, layer, ColourRole::law);
    const auto law_text = [&](int column, int row, std::string text) {
        screen.text.push_back({column, row, std::move(text), CellStyle::plain, ColourRole::law});
    };
    for (const int row : tick_rows)
        law_text(inset.title_column, row, "-");
    law_text(inset.title_column, inset.title_row, inset_title(timing, span, path.span_timings.size()));
    law_text(inset.title_column, inset.title_row + 1, "distance");
    law_text(inset.title_column + inset_columns - 9, inset.title_row + inset_rows - 1, "frame");
}

} // namespace

std::vector<PixelRect> law_inset_corners()
{
    std::vector<PixelRect> boxes;
    for (const LawInset& inset : insets())
        boxes.push_back(inset.box);
    return boxes;
}

PixelRect draw_law_inset(GraphicsScreen& screen, const EvaluatedPath& path, std::size_t span)
{
    if (span >= path.span_timings.size())
        return {};
    const std::vector<LawInset> candidates = insets();
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t>> hidden;
    for (const LawInset& candidate : candidates)
        hidden.push_back(hidden_by(screen, candidate.box));
    const LawInset& least_hidden =
        candidates[static_cast<std::size_t>(std::min_element(hidden.begin(), hidden.end()) - hidden.begin())];
    clear_box(screen, least_hidden.box);
    draw_law(screen, least_hidden, path, span);
    return least_hidden.box;
}

} // namespace apcs
