#include "apcs/raster/png_encoder.h"

#include <png.h>

#include <csetjmp>
#include <vector>

namespace apcs {

namespace {

void append_to_string(png_structp png, png_bytep data, png_size_t length)
{
    auto* output = static_cast<std::string*>(png_get_io_ptr(png));
    output->append(reinterpret_cast<const char*>(data), length);
}

void flush_nothing(png_structp) {}

} // namespace

int raster_row_of(int row, PngShape shape) { return shape == PngShape::monitor ? row * 2 / 3 : row; }

int png_rows(int raster_rows, PngShape shape)
{
    return shape == PngShape::monitor ? (raster_rows * 3 + 1) / 2 : raster_rows;
}

std::optional<std::string> encode_png(const Bitmap& bitmap, PngShape shape, PngInk ink)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    if (png == nullptr)
        return std::nullopt;
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        return std::nullopt;
    }
    std::string output;
    std::vector<png_byte> row(static_cast<std::size_t>(bitmap.width()));
    const png_byte lit = ink == PngInk::paper ? 0 : 255;
    const png_byte unlit = static_cast<png_byte>(255 - lit);
    // libpng reports errors by longjmp; nothing with a destructor is created after this point.
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return std::nullopt;
    }
    png_set_write_fn(png, &output, append_to_string, flush_nothing);
    const int rows = png_rows(bitmap.height(), shape);
    png_set_IHDR(png, info, static_cast<png_uint_32>(bitmap.width()), static_cast<png_uint_32>(rows), 8,
                 PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (shape == PngShape::raw)
        png_set_pHYs(png, info, 3, 2, PNG_RESOLUTION_UNKNOWN);
    png_write_info(png, info);
    for (int y = 0; y < rows; ++y) {
        const int source = raster_row_of(y, shape);
        for (int x = 0; x < bitmap.width(); ++x)
            row[static_cast<std::size_t>(x)] = bitmap.get(x, source) ? lit : unlit;
        png_write_row(png, row.data());
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return output;
}

} // namespace apcs
