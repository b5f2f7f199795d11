#include "apcs/raster/png_encoder.h"

#include <png.h>

#include <array>
#include <csetjmp>
#include <cstring>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace apcs {

namespace {

// libpng's reason for giving up, and the warning before it that says more ("Invalid IHDR data" after
// "Image width is zero in IHDR"), kept for the caller: fixed arrays, since nothing may allocate (or
// throw) inside libpng's C frames.
struct PngReason {
    std::array<char, 200> error{};
    std::array<char, 200> warning{};

    std::string text() const
    {
        std::string reason = error.data();
        if (warning[0] != '\0')
            reason += std::string(" (") + warning.data() + ")";
        return reason;
    }
};

void keep(std::array<char, 200>& kept, png_const_charp message)
{
    std::strncpy(kept.data(), message, kept.size() - 1);
}

// libpng's error handler: the reason kept, not printed (its default prints on stderr, over the
// curses screen), then back to write_rows's setjmp, as libpng requires of an error handler.
[[noreturn]] void keep_error(png_structp png, png_const_charp message)
{
    keep(static_cast<PngReason*>(png_get_error_ptr(png))->error, message);
    png_longjmp(png, 1);
}

// A warning does not stop the picture, and is not printed either: it is kept for the error that may
// follow it.
void keep_warning(png_structp png, png_const_charp message)
{
    keep(static_cast<PngReason*>(png_get_error_ptr(png))->warning, message);
}

// A bad_alloc must not unwind through libpng's C frames: it becomes libpng's error, outside the
// catch (a longjmp out of a handler would skip the exception's destruction).
void append_to_string(png_structp png, png_bytep data, png_size_t length)
{
    auto* output = static_cast<std::string*>(png_get_io_ptr(png));
    bool appended = true;
    try {
        output->append(reinterpret_cast<const char*>(data), length);
    } catch (const std::bad_alloc&) {
        appended = false;
    }
    if (!appended)
        png_error(png, "out of memory for the encoded picture");
}

void flush_nothing(png_structp) {}

Diagnostic png_failure(std::string reason) { return Diagnostic{"libpng", 0, std::move(reason)}; }

// The picture written through `png`; false after libpng's error. setjmp stands in this function
// alone, so that what libpng writes into the caller's locals (the output, the reason) keeps its
// value after the longjmp; nothing with a destructor is made here.
bool write_rows(png_structp png, png_infop info, const Bitmap& bitmap, PngShape shape, PngInk ink,
                std::vector<png_byte>& row)
{
    const png_byte lit = ink == PngInk::paper ? 0 : 255;
    const png_byte unlit = static_cast<png_byte>(255 - lit);
    if (setjmp(png_jmpbuf(png)))
        return false;
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
    return true;
}

} // namespace

int raster_row_of(int row, PngShape shape) { return shape == PngShape::monitor ? row * 2 / 3 : row; }

int png_rows(int raster_rows, PngShape shape)
{
    return shape == PngShape::monitor ? (raster_rows * 3 + 1) / 2 : raster_rows;
}

Expected<std::string> encode_png(const Bitmap& bitmap, PngShape shape, PngInk ink)
{
    std::string output;
    std::vector<png_byte> row(static_cast<std::size_t>(bitmap.width()));
    PngReason reason{};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &reason, keep_error, keep_warning);
    if (png == nullptr)
        return png_failure("cannot start an encoder (out of memory?)");
    png_infop info = png_create_info_struct(png);
    if (info == nullptr) {
        png_destroy_write_struct(&png, nullptr);
        return png_failure("cannot start an encoder (out of memory?)");
    }
    png_set_write_fn(png, &output, append_to_string, flush_nothing);
    const bool written = write_rows(png, info, bitmap, shape, ink, row);
    png_destroy_write_struct(&png, &info);
    if (!written)
        return png_failure(reason.text());
    return output;
}

} // namespace apcs
