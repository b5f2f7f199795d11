#include "apcs/raster/painter.h"
#include "apcs/raster/svg_encoder.h"

#include "support/xml_elements.h"

#include <catch2/catch.hpp>

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

TEST_CASE("an SVG is well-formed XML with a polyline per stroke, its dashes, marks and escaped text", "[raster][svg]")
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

    const auto polylines = elements_named(*elements, "polyline");
    REQUIRE(polylines.size() == 3);
    CHECK(polylines[0].attributes.at("points") == "10.5,15.75 100.5,15.75 100.5,75.75");
    CHECK(polylines[0].attributes.count("stroke-dasharray") == 0);
    CHECK(polylines[0].attributes.count("clip-path") == 0);
    CHECK(polylines[1].attributes.at("stroke-dasharray") == "6 4");
    CHECK(polylines[2].attributes.at("stroke-dasharray") == "1 2");
    CHECK(polylines[1].attributes.at("clip-path") == polylines[2].attributes.at("clip-path"));
    REQUIRE(elements_named(*elements, "clipPath").size() == 1);

    const auto paths = elements_named(*elements, "path");
    REQUIRE(paths.size() == 2); // the control point with its box, the arrow
    CHECK(paths[0].attributes.at("d").find("M" + svg_point_text({198, 98}) + " L" + svg_point_text({202, 102})) == 0);
    CHECK(paths[0].attributes.at("d").find(" Z") != std::string::npos);

    const auto texts = elements_named(*elements, "text");
    REQUIRE(texts.size() == 1);
    CHECK(texts[0].text == "a<b & c>d ? \xEF\xBF\xBD");
    CHECK(svg.find("a&lt;b &amp; c&gt;d") != std::string::npos);
}
