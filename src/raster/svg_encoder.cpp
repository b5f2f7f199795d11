#include "apcs/raster/svg_encoder.h"

#include "apcs/geometry/hercules.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/line_pixels.h"
#include "apcs/raster/painter.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <vector>

namespace apcs {

namespace {

// The top of a text cell to its baseline, in raster rows: the VGA font's letters end on row 11.
constexpr int text_baseline_row = 11;
// The monospace font size whose advance (about 0.6 em) is near a 9-pixel cell; textLength makes it
// exact. Bold, as the VGA font's strokes are two pixels wide: a rendering then lights nearly every
// pixel the PNG's text lights (tests/e2e/svg_renders.sh).
constexpr int text_font_size = 15;
// Lines a little wider than a pixel, so that a diagonal's pixels are covered; their square caps
// (half the width past each end) cover a run's first and last pixels.
constexpr double stroke_width = 1.25;
// Half the length of a dot's line: with its caps 1.5 tall, a raster row as the monitor showed it.
constexpr double dot_half_length = svg_row_height / 2 - stroke_width / 2;

std::string number(double value)
{
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

double svg_x(double raster_x) { return raster_x; }
double svg_y(double raster_y) { return raster_y * svg_row_height; }

// A rectangle of whole pixels, edges on the pixels' edges.
std::string rect_attributes(PixelRect rect)
{
    return "x=\"" + number(svg_x(rect.left)) + "\" y=\"" + number(svg_y(rect.top)) + "\" width=\"" +
           number(svg_x(rect.width())) + "\" height=\"" + number(svg_y(rect.height())) + "\"";
}

// Element content with &, < and > escaped; control characters (not allowed in XML) as '?', and
// malformed UTF-8 as U+FFFD, so that the document stays well-formed whatever a file name holds.
std::string escaped_text(std::string_view utf8)
{
    std::string text;
    for (const char32_t code_point : decode_utf8(utf8)) {
        if (code_point == U'&')
            text += "&amp;";
        else if (code_point == U'<')
            text += "&lt;";
        else if (code_point == U'>')
            text += "&gt;";
        else if (code_point < 0x20 || code_point == 0x7F || code_point == 0xFFFE || code_point == 0xFFFF ||
                 (code_point >= 0xD800 && code_point <= 0xDFFF))
            text += '?';
        else
            append_utf8(text, code_point);
    }
    return text;
}

// Whether two raster pixels are the same or neighbours (diagonals included).
bool touching(PixelPoint a, PixelPoint b) { return std::abs(a.x - b.x) <= 1 && std::abs(a.y - b.y) <= 1; }

// The pieces of a stroke that the Painter lit inside `box`: runs of lit pixels that follow one
// another, each kept as its first pixel, the last pixel it lit on each segment it passes through,
// and its last pixel. A dashed or dotted stroke's runs are its dashes and dots, with the PNG's
// pattern and phase; a solid stroke's are the pieces left by clipping.
std::vector<std::vector<PixelPoint>> lit_runs(const Stroke& stroke, PixelRect box)
{
    if (stroke.points.size() == 1)
        return box.contains(stroke.points.front()) ? std::vector<std::vector<PixelPoint>>{stroke.points}
                                                   : std::vector<std::vector<PixelPoint>>{};
    std::vector<std::vector<PixelPoint>> runs;
    std::vector<PixelPoint> run;
    PixelPoint last_lit;
    std::size_t last_lit_segment = 0;
    const auto close_run = [&] {
        if (run.empty())
            return;
        if (run.back() != last_lit)
            run.push_back(last_lit);
        runs.push_back(std::move(run));
        run.clear();
    };
    int phase = 0;
    for (std::size_t segment = 1; segment < stroke.points.size(); ++segment) {
        const auto take = [&](int x, int y, bool lit) {
            const PixelPoint pixel{x, y};
            if (!lit || (!run.empty() && !touching(last_lit, pixel)))
                close_run();
            if (!lit)
                return;
            if (run.empty())
                run.push_back(pixel);
            else if (segment != last_lit_segment && run.back() != last_lit)
                run.push_back(last_lit);
            last_lit = pixel;
            last_lit_segment = segment;
        };
        each_styled_pixel(stroke.points[segment - 1], stroke.points[segment], box, stroke.style, phase, take);
    }
    close_run();
    return runs;
}

// Where the raster may be drawn on: the bitmap, and the stroke's clip within it (Painter::bounds).
PixelRect visible_box(const std::optional<PixelRect>& clip, int width, int height)
{
    if (!clip)
        return {0, 0, width, height};
    return {std::max(0, clip->left), std::max(0, clip->top), std::min(width, clip->right), std::min(height, clip->bottom)};
}

// A run as path data. A run of one pixel is a short upright line whose square caps fill the pixel
// (1.25 wide, 1.5 tall): a zero-length line is drawn by some renderers and not by others.
std::string run_data(const std::vector<PixelPoint>& run)
{
    if (run.size() == 1) {
        const PixelPoint at = run.front();
        const double centre_y = svg_y(at.y + 0.5);
        return "M" + number(svg_x(at.x + 0.5)) + "," + number(centre_y - dot_half_length) + " V" +
               number(centre_y + dot_half_length);
    }
    std::string data;
    for (const PixelPoint point : run)
        data += (data.empty() ? "M" : " L") + svg_point_text(point);
    return data;
}

std::string_view style_name(LineStyle style)
{
    switch (style) {
    case LineStyle::solid: return "solid";
    case LineStyle::dashed: return "dashed";
    case LineStyle::dotted: return "dotted";
    }
    return "solid";
}

// One <path> per stroke, its visible pieces as subpaths; nothing when none of it is visible.
std::string stroke_element(const Stroke& stroke, int width, int height)
{
    std::string data;
    for (const std::vector<PixelPoint>& run : lit_runs(stroke, visible_box(stroke.clip, width, height)))
        data += (data.empty() ? "" : " ") + run_data(run);
    if (data.empty())
        return {};
    const std::string clipped = stroke.clip ? " clipped" : "";
    return "<path class=\"" + std::string(style_name(stroke.style)) + clipped + "\" d=\"" + data + "\"/>\n";
}

// Path data of straight segments between pixel centres.
std::string segment(PixelPoint from, PixelPoint to)
{
    return "M" + svg_point_text(from) + " L" + svg_point_text(to) + " ";
}

// The shapes of graphics_screen.cpp's draw_mark_pixels, as vector lines.
std::string mark_element(const PixelMark& mark)
{
    const PixelPoint at = mark.at;
    std::string path;
    switch (mark.kind) {
    case MarkKind::control_point:
        path = segment({at.x - 2, at.y - 2}, {at.x + 2, at.y + 2}) + segment({at.x - 2, at.y + 2}, {at.x + 2, at.y - 2});
        if (mark.style == CellStyle::reverse)
            path += segment({at.x - 4, at.y - 4}, {at.x + 4, at.y - 4}) + "L" + svg_point_text({at.x + 4, at.y + 4}) +
                    " L" + svg_point_text({at.x - 4, at.y + 4}) + " Z ";
        break;
    case MarkKind::inbetween:
        return "<rect " + rect_attributes({at.x - 1, at.y - 1, at.x + 2, at.y + 2}) + " fill=\"white\" stroke=\"none\"/>\n";
    case MarkKind::arrow:
        path = segment({at.x - 16, at.y}, {at.x - 5, at.y}) + segment({at.x - 8, at.y - 3}, {at.x - 5, at.y}) +
               segment({at.x - 8, at.y + 3}, {at.x - 5, at.y});
        break;
    case MarkKind::staff_value:
        path = segment({at.x - 1, at.y - 4}, {at.x - 1, at.y + 4}) + segment({at.x + 1, at.y - 4}, {at.x + 1, at.y + 4});
        break;
    case MarkKind::tangent_end:
        path = segment({at.x - 2, at.y}, {at.x + 2, at.y}) + segment({at.x, at.y - 2}, {at.x, at.y + 2});
        break;
    case MarkKind::goal:
        path = segment({at.x - 5, at.y}, {at.x, at.y - 5}) + "L" + svg_point_text({at.x + 5, at.y}) + " L" +
               svg_point_text({at.x, at.y + 5}) + " Z ";
        break;
    }
    path.pop_back();
    return "<path class=\"mark\" d=\"" + path + "\"/>\n";
}

std::string text_element(const TextLine& line)
{
    // The cells the raster draws: a combining mark takes none (Painter::text).
    const std::u32string characters = decode_utf8(line.text);
    const auto cells = static_cast<std::size_t>(
        std::count_if(characters.begin(), characters.end(), [](char32_t c) { return cell_width(c) != 0; }));
    const int baseline = hercules::text_row_top(line.row) + text_baseline_row;
    return "<text x=\"" + number(svg_x(line.column * hercules::cell_width)) + "\" y=\"" + number(svg_y(baseline)) +
           "\" textLength=\"" + std::to_string(cells * hercules::cell_width) + "\" lengthAdjust=\"spacingAndGlyphs\">" +
           escaped_text(line.text) + "</text>\n";
}

} // namespace

std::string svg_point_text(PixelPoint pixel)
{
    return number(svg_x(pixel.x + 0.5)) + "," + number(svg_y(pixel.y + 0.5));
}

std::string encode_svg(const GraphicsScreen& screen)
{
    const int width = screen.bitmap.width();
    const std::string height = number(svg_y(screen.bitmap.height()));
    std::string lines;
    for (const Stroke& stroke : screen.strokes)
        lines += stroke_element(stroke, width, screen.bitmap.height());
    for (const TickedLine& line : screen.ticked_lines)
        for (const Stroke& stroke : ticked_line_strokes(line))
            lines += stroke_element(stroke, width, screen.bitmap.height());
    std::string text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                       "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
                       height + "\" viewBox=\"0 0 " + std::to_string(width) + " " + height + "\">\n";
    text += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(width) + "\" height=\"" + height + "\" fill=\"black\"/>\n";
    text += "<g fill=\"none\" stroke=\"white\" stroke-width=\"" + number(stroke_width) +
            "\" stroke-linecap=\"square\">\n" + lines;
    for (const PixelMark& mark : screen.marks)
        text += mark_element(mark);
    text += "</g>\n<g fill=\"white\" font-family=\"monospace\" font-size=\"" + std::to_string(text_font_size) +
            "\" font-weight=\"bold\" xml:space=\"preserve\">\n";
    for (const TextLine& line : screen.text)
        if (!line.text.empty())
            text += text_element(line);
    return text + "</g>\n</svg>\n";
}

} // namespace apcs
