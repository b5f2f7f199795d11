#include "apcs/raster/painter.h"
#include "apcs/raster/png_encoder.h"

#include <catch2/catch.hpp>

#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>
#include <utility>
#include <vector>

using namespace apcs;

namespace {

struct Decoded {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    std::vector<png_byte> pixels;
};

Decoded decode(const std::string& bytes)
{
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()) != 0);
    image.format = PNG_FORMAT_GRAY;
    Decoded decoded{image.width, image.height, std::vector<png_byte>(PNG_IMAGE_SIZE(image))};
    REQUIRE(png_image_finish_read(&image, nullptr, decoded.pixels.data(), 0, nullptr) != 0);
    return decoded;
}

} // namespace

// The pixels per unit of a PNG's pHYs chunk, x then y; {0, 0} when it has none.
std::pair<png_uint_32, png_uint_32> pixel_aspect(const std::string& bytes)
{
    const std::size_t chunk = bytes.find("pHYs");
    if (chunk == std::string::npos || chunk + 12 > bytes.size())
        return {0, 0};
    const auto big_endian = [&bytes](std::size_t at) {
        png_uint_32 value = 0;
        for (std::size_t i = 0; i < 4; ++i)
            value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
        return value;
    };
    return {big_endian(chunk + 4), big_endian(chunk + 8)};
}

TEST_CASE("a raw PNG reads back with libpng as the same 720x348 raster, white on black, pixels 3:2", "[raster][png]")
{
    Bitmap bitmap;
    Painter painter(bitmap);
    painter.line({0, 0}, {719, 347});
    painter.cross_marker({360, 100});
    const auto png = encode_png(bitmap, PngShape::raw);
    REQUIRE(png.has_value());
    const Decoded decoded = decode(*png);
    REQUIRE(decoded.width == 720);
    REQUIRE(decoded.height == 348);
    std::size_t mismatches = 0;
    std::size_t white = 0;
    for (int y = 0; y < 348; ++y)
        for (int x = 0; x < 720; ++x) {
            const png_byte value = decoded.pixels[static_cast<std::size_t>(y) * 720 + static_cast<std::size_t>(x)];
            mismatches += value != (bitmap.get(x, y) ? 255 : 0) ? 1u : 0u;
            white += value == 255 ? 1u : 0u;
        }
    REQUIRE(mismatches == 0);
    REQUIRE(white == bitmap.lit_count());
    // 3 pixels per unit across, 2 down: a pixel 1.5 times taller than wide, as on the monitor.
    REQUIRE(pixel_aspect(*png) == std::pair<png_uint_32, png_uint_32>{3, 2});
}

TEST_CASE("a monitor PNG is 720x522: every raster row 1.5 pixels tall, rows repeated nearest-neighbour", "[raster][png]")
{
    Bitmap bitmap;
    // Each raster row y lit at x = y only, so every picture row tells which raster row it shows.
    for (int y = 0; y < bitmap.height(); ++y)
        bitmap.set(y, y, true);
    const auto png = encode_png(bitmap, PngShape::monitor);
    REQUIRE(png.has_value());
    const Decoded decoded = decode(*png);
    REQUIRE(decoded.width == 720);
    REQUIRE(decoded.height == 522);
    REQUIRE(pixel_aspect(*png) == std::pair<png_uint_32, png_uint_32>{0, 0});
    std::vector<int> shown;
    for (std::size_t row = 0; row < 522; ++row)
        for (std::size_t x = 0; x < 720; ++x)
            if (decoded.pixels[row * 720 + x] == 255)
                shown.push_back(static_cast<int>(x));
    REQUIRE(shown.size() == 522);
    // Rows 0 1 2 | 3 4 5 show raster rows 0 0 1 | 2 2 3: even rows twice, odd rows once.
    CHECK(std::vector<int>(shown.begin(), shown.begin() + 6) == std::vector<int>{0, 0, 1, 2, 2, 3});
    CHECK(shown.back() == 347);
    for (std::size_t row = 1; row < shown.size(); ++row)
        REQUIRE(shown[row] - shown[row - 1] <= 1);
}

TEST_CASE("a PNG in paper ink is black on white: a lit pixel 0, an unlit one 255", "[raster][png]")
{
    Bitmap bitmap(16, 4);
    bitmap.set(3, 1, true);
    const Expected<std::string> monitor = encode_png(bitmap, PngShape::raw);
    const Expected<std::string> paper = encode_png(bitmap, PngShape::raw, PngInk::paper);
    REQUIRE(monitor);
    REQUIRE(paper);
    const Decoded on_monitor = decode(*monitor);
    const Decoded on_paper = decode(*paper);
    REQUIRE(on_paper.width == 16);
    REQUIRE(on_paper.height == 4);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 16; ++x) {
            const std::size_t at = static_cast<std::size_t>(y * 16 + x);
            const bool lit = x == 3 && y == 1;
            CAPTURE(x, y);
            REQUIRE(on_monitor.pixels[at] == (lit ? 255 : 0));
            REQUIRE(on_paper.pixels[at] == (lit ? 0 : 255));
        }
    }
}

TEST_CASE("libpng's refusal comes back as its reason, and nothing is printed over the screen", "[raster][png]")
{
    // What libpng writes on standard error (its default handler's "libpng error: …") goes to a file.
    std::string caught = (std::filesystem::temp_directory_path() / "apcs-png-stderr-XXXXXX").string();
    const int file = ::mkstemp(caught.data());
    REQUIRE(file >= 0);
    std::fflush(stderr);
    const int saved = ::dup(STDERR_FILENO);
    ::dup2(file, STDERR_FILENO);
    const Expected<std::string> no_columns = encode_png(Bitmap(0, 4), PngShape::raw);
    std::fflush(stderr);
    ::dup2(saved, STDERR_FILENO);
    ::close(saved);
    ::close(file);
    std::stringstream printed;
    printed << std::ifstream(caught).rdbuf();
    std::filesystem::remove(caught);

    REQUIRE_FALSE(no_columns);
    CHECK(no_columns.error().to_string() == "libpng: Invalid IHDR data (Image width is zero in IHDR)");
    CHECK(printed.str().empty());
}
