#include "apcs/raster/font.h"
#include "apcs/raster/painter.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <vector>

using namespace apcs;

namespace {

std::vector<PixelPoint> lit_pixels(const Bitmap& bitmap)
{
    std::vector<PixelPoint> pixels;
    for (int y = 0; y < bitmap.height(); ++y)
        for (int x = 0; x < bitmap.width(); ++x)
            if (bitmap.get(x, y))
                pixels.push_back({x, y});
    return pixels;
}

} // namespace

TEST_CASE("Bresenham lines in all 8 octants hit both ends with one pixel per major step", "[raster][painter]")
{
    const PixelPoint centre{50, 40};
    const std::vector<PixelPoint> ends{{70, 45}, {55, 60}, {45, 60}, {30, 45}, {30, 35}, {45, 20}, {55, 20}, {70, 35}};
    for (const PixelPoint end : ends) {
        Bitmap bitmap(100, 80);
        Painter(bitmap).line(centre, end);
        CAPTURE(end.x, end.y);
        REQUIRE(bitmap.get(centre.x, centre.y));
        REQUIRE(bitmap.get(end.x, end.y));
        const int major = std::max(std::abs(end.x - centre.x), std::abs(end.y - centre.y));
        REQUIRE(bitmap.lit_count() == static_cast<std::size_t>(major + 1));
        // Each pixel lies within half a pixel of the ideal line.
        for (const PixelPoint p : lit_pixels(bitmap)) {
            const double dx = end.x - centre.x;
            const double dy = end.y - centre.y;
            const double off = std::abs(dy * (p.x - centre.x) - dx * (p.y - centre.y)) / std::max(std::abs(dx), std::abs(dy));
            REQUIRE(off <= 0.5 + 1e-9);
        }
    }
}

TEST_CASE("a line from 0,0 to 5,2 lights the pixels worked by hand", "[raster][painter]")
{
    // y = 0.4x: 0, 0.4, 0.8, 1.2, 1.6, 2 round to 0, 0, 1, 1, 2, 2.
    Bitmap bitmap(10, 10);
    Painter(bitmap).line({0, 0}, {5, 2});
    REQUIRE(lit_pixels(bitmap) == std::vector<PixelPoint>{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}});
}

TEST_CASE("lines are clipped to the bitmap and far ends cost nothing", "[raster][painter]")
{
    Bitmap bitmap(20, 10);
    Painter painter(bitmap);
    painter.line({-1000000, 5}, {1000000, 5});
    REQUIRE(bitmap.lit_count() == 20);
    bitmap.clear();
    painter.line({-50, -50}, {-10, -5});
    REQUIRE(bitmap.lit_count() == 0);
    painter.line({-5, -5}, {24, 24}); // the diagonal through (0,0) … (9,9)
    REQUIRE(bitmap.lit_count() == 10);
    REQUIRE(bitmap.get(9, 9));
}

TEST_CASE("the control-point marker is an x of 5x5 pixels", "[raster][painter]")
{
    Bitmap bitmap(9, 9);
    Painter(bitmap).cross_marker({4, 4});
    REQUIRE(bitmap.lit_count() == 9);
    for (int d = -2; d <= 2; ++d) {
        REQUIRE(bitmap.get(4 + d, 4 + d));
        REQUIRE(bitmap.get(4 + d, 4 - d));
    }
    REQUIRE_FALSE(bitmap.get(4, 2));
}

TEST_CASE("XOR drawing of the arrow erases it again and keeps what was under it", "[raster][painter]")
{
    Bitmap bitmap(40, 40);
    Painter painter(bitmap);
    painter.line({0, 10}, {39, 10});
    const Bitmap before = bitmap;
    painter.arrow({10, 5}, DrawMode::toggle);
    REQUIRE_FALSE(bitmap == before);
    REQUIRE(bitmap.get(10, 5));
    painter.arrow({10, 5}, DrawMode::toggle);
    REQUIRE(bitmap == before);
}

TEST_CASE("text is drawn from the VGA font in 9x14 cells", "[raster][painter]")
{
    Bitmap bitmap(18, 14);
    Painter(bitmap).text({0, 0}, "|-");
    std::size_t bar = 0;
    std::size_t dash = 0;
    for (int y = 0; y < 14; ++y)
        for (int x = 0; x < 18; ++x) {
            REQUIRE(bitmap.get(x, y) == Font::pixel(x < 9 ? U'|' : U'-', x % 9, y));
            (x < 9 ? bar : dash) += bitmap.get(x, y) ? 1u : 0u;
        }
    REQUIRE(bar > 0);
    REQUIRE(dash > 0);
}

TEST_CASE("the 9th font column repeats the 8th only for box drawing", "[raster][font]")
{
    REQUIRE(Font::has_glyph(U'\u2500'));
    for (int row = 0; row < 14; ++row) {
        REQUIRE(Font::pixel(U'\u2500', 8, row) == Font::pixel(U'\u2500', 7, row));
        REQUIRE_FALSE(Font::pixel(U'A', 8, row));
    }
    REQUIRE(Font::has_glyph(U'A'));
    REQUIRE_FALSE(Font::has_glyph(U'\u4E00'));
}

TEST_CASE("UTF-8 decoding", "[raster][painter]")
{
    REQUIRE(decode_utf8("a\xC3\xA9\xE2\x94\x80") == U"a\u00E9\u2500");
    REQUIRE(decode_utf8("\xFF") == U"\uFFFD");
}

TEST_CASE("a clipped painter draws nothing outside its clip rectangle", "[raster][painter]")
{
    Bitmap bitmap;
    Painter clipped(bitmap, PixelRect{10, 10, 20, 20});
    clipped.line({0, 15}, {100, 15});
    clipped.pixel({5, 5});
    clipped.pixel({12, 12});
    int lit = 0;
    for (int y = 0; y < bitmap.height(); ++y)
        for (int x = 0; x < bitmap.width(); ++x)
            if (bitmap.get(x, y)) {
                ++lit;
                REQUIRE((x >= 10 && x < 20 && y >= 10 && y < 20));
            }
    // The line's 10 pixels from x = 10 to 19, and the one pixel inside.
    REQUIRE(lit == 11);
}

TEST_CASE("a run along a row lights what setting its pixels one by one lights, across bytes and off the raster",
          "[raster][bitmap]")
{
    const std::vector<std::pair<int, int>> runs{{0, 0},   {3, 5},     {5, 3},     {7, 8},   {8, 15}, {0, 719},
                                                {-5, 12}, {700, 900}, {-9, -1},   {720, 800}, {13, 13}, {6, 17},
                                                {17, 6},  {1, 710},   {715, 719}, {16, 23}};
    for (const auto& [first, last] : runs) {
        for (const int y : {0, 200, 347, -1, 348}) {
            CAPTURE(first, last, y);
            Bitmap run;
            Bitmap one_by_one;
            // A row with something lit already: a run adds to it.
            for (int x = 0; x < 720; x += 7) {
                run.set(x, y, true);
                one_by_one.set(x, y, true);
            }
            run.set_run(y, first, last);
            for (int x = std::min(first, last); x <= std::max(first, last); ++x)
                one_by_one.set(x, y, true);
            REQUIRE(run == one_by_one);
        }
    }
}
