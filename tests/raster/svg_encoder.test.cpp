#include "apcs/raster/line_pixels.h"
#include "apcs/raster/painter.h"
#include "apcs/raster/svg_encoder.h"

#include "support/xml_elements.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;
using test::elements_named;
using test::XmlReader;

TEST_CASE("a pixel's centre is written with rows 1.5 units tall, as the monitor showed it", "[raster][svg]")
{
    CHECK(svg_point_text({10, 20}) == "10.5,30.75");
    CHECK(svg_point_text({0, 1}) == "0.5,2.25");
    CHECK(svg_point_text({719, 347}) == "719.5,521.25");
}

TEST_CASE("a Painter given a record keeps the lines it sets, one polyline per run of segments", "[raster][svg]")
{
    Bitmap bitmap(100, 80);
    std::vector<Stroke> strokes;
    Painter painter(bitmap, PixelRect{5, 5, 95, 75});
    painter.record_into(strokes);
    int phase = 0;
    painter.styled_line({10, 10}, {40, 30}, LineStyle::dashed, phase);
    painter.styled_line({40, 30}, {60, 12}, LineStyle::dashed, phase);
    painter.line({20, 60}, {80, 60});
    painter.line({50, 50}, {50, 70}, DrawMode::toggle);
    painter.pixel({70, 70});
    painter.pixel({71, 70}, DrawMode::clear);

    REQUIRE(strokes.size() == 3);
    CHECK(strokes[0].points == std::vector<PixelPoint>{{10, 10}, {40, 30}, {60, 12}});
    CHECK(strokes[0].style == LineStyle::dashed);
    REQUIRE(strokes[0].clip);
    CHECK(strokes[0].clip->left == 5);
    CHECK(strokes[0].clip->bottom == 75);
    CHECK(strokes[1].points == std::vector<PixelPoint>{{20, 60}, {80, 60}});
    CHECK(strokes[1].style == LineStyle::solid);
    CHECK(strokes[2].points == std::vector<PixelPoint>{{70, 70}});
}

TEST_CASE("the strokes recorded are the pixels drawn: every segment's end pixels are lit", "[raster][svg]")
{
    Bitmap bitmap(120, 90);
    std::vector<Stroke> strokes;
    Painter painter(bitmap);
    painter.record_into(strokes).rectangle({0, 0, 120, 90});
    const std::vector<PixelPoint> zigzag{{10, 10}, {50, 70}, {90, 15}, {110, 80}};
    int phase = 0;
    for (std::size_t i = 1; i < zigzag.size(); ++i)
        painter.styled_line(zigzag[i - 1], zigzag[i], LineStyle::solid, phase);
    REQUIRE(strokes.size() == 5);
    CHECK(strokes.back().points == zigzag);
    for (const Stroke& stroke : strokes)
        for (const PixelPoint point : stroke.points)
            CHECK(bitmap.get(point.x, point.y));
}

TEST_CASE("raster pixels are the same whether or not a Painter records", "[raster][svg]")
{
    Bitmap plain(80, 60);
    Bitmap recorded(80, 60);
    std::vector<Stroke> strokes;
    Painter plain_painter(plain, PixelRect{2, 2, 78, 58});
    Painter recording_painter(recorded, PixelRect{2, 2, 78, 58});
    recording_painter.record_into(strokes);
    for (Painter* painter : {&plain_painter, &recording_painter}) {
        int phase = 0;
        painter->styled_line({-10, 5}, {70, 50}, LineStyle::dotted, phase);
        painter->line({0, 30}, {79, 30});
        painter->pixel({40, 40});
    }
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x)
            REQUIRE(plain.get(x, y) == recorded.get(x, y));
}

namespace {

// The path data of the SVG's strokes of class `style_class` (e.g. "dashed clipped"), in order.
std::vector<std::string> stroke_data(const std::string& svg, const std::string& style_class)
{
    const auto elements = XmlReader::read(svg);
    REQUIRE(elements);
    std::vector<std::string> data;
    for (const auto& path : elements_named(*elements, "path"))
        if (path.attributes.at("class") == style_class)
            data.push_back(path.attributes.at("d"));
    return data;
}

GraphicsScreen screen_of(std::vector<Stroke> strokes)
{
    GraphicsScreen screen;
    screen.strokes = std::move(strokes);
    return screen;
}

// The raster pixel whose centre an SVG coordinate pair names (rows 1.5 units tall).
PixelPoint pixel_at(double x, double y)
{
    return {static_cast<int>(std::lround(x - 0.5)), static_cast<int>(std::lround(y / svg_row_height - 0.5))};
}

// The pixels an SVG path's subpaths pass through, each straight piece walked as a raster line: a
// dot ("M x,y0 V y1") is the pixel at its middle.
Bitmap pixels_of(const std::vector<std::string>& data, int width, int height)
{
    Bitmap pixels(width, height);
    for (const std::string& path : data) {
        std::istringstream words(path);
        std::string word;
        PixelPoint last{};
        double last_x = 0.0;
        double last_y = 0.0;
        while (words >> word) {
            const char command = word.front();
            if (command == 'V') {
                const double end_y = std::stod(word.substr(1));
                const PixelPoint dot = pixel_at(last_x, (last_y + end_y) / 2);
                pixels.set(dot.x, dot.y, true);
                continue;
            }
            const std::size_t comma = word.find(',');
            last_x = std::stod(word.substr(1, comma - 1));
            last_y = std::stod(word.substr(comma + 1));
            const PixelPoint point = pixel_at(last_x, last_y);
            const PixelPoint from = command == 'M' ? point : last;
            each_line_pixel(from, point, {0, 0, width, height}, [&](int x, int y) { pixels.set(x, y, true); });
            last = point;
        }
    }
    return pixels;
}

// The lit pixels of `drawn` that have no lit pixel of `other` within one pixel.
int pixels_without_neighbour(const Bitmap& drawn, const Bitmap& other)
{
    int lonely = 0;
    for (int y = 0; y < drawn.height(); ++y)
        for (int x = 0; x < drawn.width(); ++x) {
            bool near = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    near = near || (x + dx >= 0 && y + dy >= 0 && x + dx < other.width() && y + dy < other.height() &&
                                    other.get(x + dx, y + dy));
            lonely += drawn.get(x, y) && !near ? 1 : 0;
        }
    return lonely;
}

} // namespace

TEST_CASE("an SVG dashes with the PNG's pattern and phase: 6 on, 4 off, running on round a corner", "[raster][svg]")
{
    const auto screen = screen_of({{{{10, 10}, {22, 10}, {22, 27}}, LineStyle::dashed, std::nullopt}});
    CHECK(stroke_data(encode_svg(screen), "dashed") ==
          std::vector<std::string>{"M10.5,15.75 L15.5,15.75 M20.5,15.75 L22.5,15.75 L22.5,20.25 M22.5,27.75 L22.5,35.25"});
}

TEST_CASE("an SVG dots with the PNG's pattern: 1 on, 2 off, each dot a line whose caps fill its pixel", "[raster][svg]")
{
    const auto screen = screen_of({{{{10, 10}, {20, 10}}, LineStyle::dotted, std::nullopt}});
    CHECK(stroke_data(encode_svg(screen), "dotted") ==
          std::vector<std::string>{"M10.5,15.625 V15.875 M13.5,15.625 V15.875 M16.5,15.625 V15.875 M19.5,15.625 V15.875"});
}

TEST_CASE("an SVG stroke is cut where its clip cuts it: only the pieces inside, no clip path", "[raster][svg]")
{
    const auto screen = screen_of({{{{0, 50}, {100, 50}}, LineStyle::solid, PixelRect{20, 0, 80, 100}},
                                   {{{30, 10}, {30, 300}, {40, 300}, {40, 20}}, LineStyle::solid, PixelRect{0, 0, 720, 200}},
                                   {{{500, 500}, {600, 600}}, LineStyle::solid, std::nullopt}});
    const std::string svg = encode_svg(screen);
    CHECK(stroke_data(svg, "solid clipped") ==
          std::vector<std::string>{"M20.5,75.75 L79.5,75.75", "M30.5,15.75 L30.5,299.25 M40.5,299.25 L40.5,30.75"});
    // The second's segment back in starts on the clip's last row: a segment's first pixel is
    // skipped as the last one's end only when it is its start, and this one starts outside, where
    // nothing was drawn (Painter::styled_line alike); the third lies wholly below the raster.
    CHECK(stroke_data(svg, "solid").empty());
    CHECK(svg.find("clip") == svg.find("clipped"));
    CHECK(svg.find("dasharray") == std::string::npos);
}

TEST_CASE("an SVG's pieces are within one pixel of every pixel the Painter lit, and the other way round", "[raster][svg]")
{
    const std::vector<PixelPoint> zigzag{{-30, 40}, {50, 330}, {130, 12}, {170, 200}, {260, 90}, {700, 340}};
    for (const LineStyle style : {LineStyle::solid, LineStyle::dashed, LineStyle::dotted}) {
        Bitmap bitmap(720, 348);
        GraphicsScreen screen;
        Painter painter(bitmap, PixelRect{15, 20, 600, 300});
        painter.record_into(screen.strokes);
        int phase = 0;
        for (std::size_t i = 1; i < zigzag.size(); ++i)
            painter.styled_line(zigzag[i - 1], zigzag[i], style, phase);
        const std::string style_class = style == LineStyle::solid ? "solid" : style == LineStyle::dashed ? "dashed" : "dotted";
        const Bitmap drawn = pixels_of(stroke_data(encode_svg(screen), style_class + " clipped"), 720, 348);
        INFO(style_class);
        CHECK(pixels_without_neighbour(bitmap, drawn) == 0);
        CHECK(pixels_without_neighbour(drawn, bitmap) == 0);
    }
}

TEST_CASE("an SVG is well-formed XML with a path per stroke, marks and escaped text", "[raster][svg]")
{
    GraphicsScreen screen;
    screen.strokes.push_back({{{10, 10}, {100, 10}, {100, 50}}, LineStyle::solid, std::nullopt});
    screen.strokes.push_back({{{20, 20}, {60, 80}}, LineStyle::dashed, PixelRect{1, 1, 300, 200}});
    screen.strokes.push_back({{{30, 30}, {90, 40}}, LineStyle::dotted, PixelRect{1, 1, 300, 200}});
    screen.strokes.push_back({{{5, 6}}, LineStyle::solid, std::nullopt});
    screen.marks.push_back({{200, 100}, MarkKind::control_point, CellStyle::reverse});
    screen.marks.push_back({{220, 100}, MarkKind::inbetween});
    screen.marks.push_back({{240, 100}, MarkKind::arrow});
    screen.text.push_back({1, 18, "a<b & c>d \x01 \xff"});

    const std::string svg = encode_svg(screen);
    const auto elements = XmlReader::read(svg);
    REQUIRE(elements);
    REQUIRE(elements->front().name == "svg");
    CHECK(elements->front().attributes.at("viewBox") == "0 0 720 522");

    CHECK(stroke_data(svg, "solid") == std::vector<std::string>{"M10.5,15.75 L100.5,15.75 L100.5,75.75", "M5.5,9.625 V9.875"});
    CHECK(stroke_data(svg, "dashed clipped").size() == 1);
    CHECK(stroke_data(svg, "dotted clipped").size() == 1);

    const auto marks = stroke_data(svg, "mark");
    REQUIRE(marks.size() == 2); // the control point with its box, the arrow
    CHECK(marks[0].find("M" + svg_point_text({198, 98}) + " L" + svg_point_text({202, 102})) == 0);
    CHECK(marks[0].find(" Z") != std::string::npos);

    const auto texts = elements_named(*elements, "text");
    REQUIRE(texts.size() == 1);
    CHECK(texts[0].text == "a<b & c>d ? \xEF\xBF\xBD");
    CHECK(svg.find("a&lt;b &amp; c&gt;d") != std::string::npos);
}
