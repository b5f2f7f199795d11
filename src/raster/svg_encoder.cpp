#include "apcs/raster/svg_encoder.h"

#include "apcs/geometry/hercules.h"
#include "apcs/raster/cell_grid.h"
#include "apcs/raster/painter.h"

#include <charconv>
#include <optional>
#include <string_view>
#include <vector>

namespace apcs {

namespace {

// The top of a text cell to its baseline, in raster rows: the VGA font's letters end on row 11.
constexpr int text_baseline_row = 11;
// The monospace font size whose advance (about 0.6 em) is near a 9-pixel cell; textLength makes it exact.
constexpr int text_font_size = 15;

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

// Each distinct clip rectangle becomes one <clipPath>; strokes name theirs by index.
class ClipPaths {
public:
    std::string attribute(const std::optional<PixelRect>& clip)
    {
        if (!clip)
            return {};
        std::size_t index = 0;
        while (index < m_rects.size() && !same(m_rects[index], *clip))
            ++index;
        if (index == m_rects.size())
            m_rects.push_back(*clip);
        return " clip-path=\"url(#clip" + std::to_string(index) + ")\"";
    }
    std::string definitions() const
    {
        std::string text = "<defs>\n";
        for (std::size_t i = 0; i < m_rects.size(); ++i)
            text += "<clipPath id=\"clip" + std::to_string(i) + "\"><rect " + rect_attributes(m_rects[i]) +
                    "/></clipPath>\n";
        return text + "</defs>\n";
    }

private:
    static bool same(PixelRect a, PixelRect b)
    {
        return a.left == b.left && a.top == b.top && a.right == b.right && a.bottom == b.bottom;
    }
    std::vector<PixelRect> m_rects;
};

std::string dash_attribute(LineStyle style)
{
    switch (style) {
    case LineStyle::solid: return {};
    case LineStyle::dashed: return " stroke-dasharray=\"6 4\"";
    case LineStyle::dotted: return " stroke-dasharray=\"1 2\"";
    }
    return {};
}

std::string stroke_element(const Stroke& stroke, ClipPaths& clips)
{
    if (stroke.points.size() == 1) {
        const PixelPoint at = stroke.points.front();
        return "<rect " + rect_attributes({at.x, at.y, at.x + 1, at.y + 1}) + " fill=\"white\" stroke=\"none\"" +
               clips.attribute(stroke.clip) + "/>\n";
    }
    std::string points;
    for (const PixelPoint point : stroke.points)
        points += (points.empty() ? "" : " ") + svg_point_text(point);
    return "<polyline points=\"" + points + "\"" + dash_attribute(stroke.style) + clips.attribute(stroke.clip) + "/>\n";
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
    }
    path.pop_back();
    return "<path d=\"" + path + "\"/>\n";
}

std::string text_element(const TextLine& line)
{
    const std::size_t cells = decode_utf8(line.text).size();
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
    ClipPaths clips;
    std::string lines;
    for (const Stroke& stroke : screen.strokes)
        lines += stroke_element(stroke, clips);
    std::string text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                       "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
                       height + "\" viewBox=\"0 0 " + std::to_string(width) + " " + height + "\">\n";
    text += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(width) + "\" height=\"" + height + "\" fill=\"black\"/>\n";
    text += clips.definitions();
    text += "<g fill=\"none\" stroke=\"white\" stroke-width=\"1.2\">\n" + lines;
    for (const PixelMark& mark : screen.marks)
        text += mark_element(mark);
    text += "</g>\n<g fill=\"white\" font-family=\"monospace\" font-size=\"" + std::to_string(text_font_size) +
            "\" xml:space=\"preserve\">\n";
    for (const TextLine& line : screen.text)
        if (!line.text.empty())
            text += text_element(line);
    return text + "</g>\n</svg>\n";
}

} // namespace apcs
