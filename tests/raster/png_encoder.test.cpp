#include "apcs/raster/painter.h"
#include "apcs/raster/png_encoder.h"

#include <catch2/catch.hpp>

#include <png.h>

#include <cstring>
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

TEST_CASE("a PNG reads back with libpng as the same 720x348 raster, white on black", "[raster][png]")
{
    Bitmap bitmap;
    Painter painter(bitmap);
    painter.line({0, 0}, {719, 347});
    painter.cross_marker({360, 100});
    const auto png = encode_png(bitmap);
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
}
