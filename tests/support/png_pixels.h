#pragma once

#include <png.h>

#include <cstring>
#include <string>
#include <vector>

namespace apcs::test {

// A PNG's pixels as 8-bit grey, row by row; empty when the bytes are not a PNG libpng reads.
struct GreyPicture {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    std::vector<png_byte> pixels;

    bool lit(png_uint_32 x, png_uint_32 y) const { return pixels[static_cast<std::size_t>(y) * width + x] > 127; }
};

inline GreyPicture grey_picture(const std::string& bytes)
{
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()) == 0)
        return {};
    image.format = PNG_FORMAT_GRAY;
    GreyPicture picture{image.width, image.height, std::vector<png_byte>(PNG_IMAGE_SIZE(image))};
    if (png_image_finish_read(&image, nullptr, picture.pixels.data(), 0, nullptr) == 0)
        return {};
    return picture;
}

} // namespace apcs::test
