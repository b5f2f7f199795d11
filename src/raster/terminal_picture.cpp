#include "apcs/raster/terminal_picture.h"

#include "apcs/raster/png_encoder.h"

#include <chafa.h>

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

namespace apcs {

namespace {

constexpr int bytes_per_pixel = 4; // CHAFA_PIXEL_RGBA8_UNASSOCIATED

int raster_row_of_monitor(int row) { return raster_row_of(row, PngShape::monitor); }

// `rows` rows as the monitor showed them, opaque RGBA: lit pixels white, the others black; row y
// is the bitmap's row `source_row(y)`.
template <typename SourceRow>
std::vector<std::uint8_t> monitor_rgba(const Bitmap& bitmap, int rows, SourceRow source_row)
{
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(bitmap.width()) * static_cast<std::size_t>(rows) *
                                     bytes_per_pixel);
    std::size_t at = 0;
    for (int y = 0; y < rows; ++y) {
        const int source = source_row(y);
        for (int x = 0; x < bitmap.width(); ++x) {
            const std::uint8_t level = bitmap.get(x, source) ? 255 : 0;
            pixels[at++] = level;
            pixels[at++] = level;
            pixels[at++] = level;
            pixels[at++] = 255;
        }
    }
    return pixels;
}

struct ConfigRelease {
    void operator()(ChafaCanvasConfig* config) const { chafa_canvas_config_unref(config); }
};
struct CanvasRelease {
    void operator()(ChafaCanvas* canvas) const { chafa_canvas_unref(canvas); }
};

// How libchafa chooses a sixel picture's colour registers. `true_colour`: a palette of its own per
// picture (black and white are entries as they are, among others it makes). `white_and_black`:
// register 0 white, 1 black, in every picture alike: a VT340 (and xterm playing one) shares its
// registers among the pictures on the screen, so a later band that defined register 5 as grey
// turned an earlier band's white pixels of register 5 grey (seen in xterm 379 at 170x55).
enum class SixelRegisters { true_colour, white_and_black };

// libchafa's configuration for an exact picture: its registers as `registers` says, no dithering,
// the cells a picture of `width` x `height` pixels fills.
std::unique_ptr<ChafaCanvasConfig, ConfigRelease> exact_config(int width, int height, CellPixels cell,
                                                               TerminalPictureProtocol protocol,
                                                               SixelRegisters registers)
{
    std::unique_ptr<ChafaCanvasConfig, ConfigRelease> config(chafa_canvas_config_new());
    chafa_canvas_config_set_pixel_mode(config.get(), protocol == TerminalPictureProtocol::sixel
                                                         ? CHAFA_PIXEL_MODE_SIXELS
                                                         : CHAFA_PIXEL_MODE_KITTY);
    // Foreground and background are white and black by default: FGBG draws lit pixels white.
    chafa_canvas_config_set_canvas_mode(config.get(), registers == SixelRegisters::white_and_black
                                                          ? CHAFA_CANVAS_MODE_FGBG
                                                          : CHAFA_CANVAS_MODE_TRUECOLOR);
    chafa_canvas_config_set_dither_mode(config.get(), CHAFA_DITHER_MODE_NONE);
    chafa_canvas_config_set_cell_geometry(config.get(), cell.width, cell.height);
    chafa_canvas_config_set_geometry(config.get(), cells_holding(width, cell.width), cells_holding(height, cell.height));
    return config;
}

// libchafa 1.12 (Debian 12) base64-encodes each 512-byte chunk of a kitty picture on its own and
// writes a chunk's last byte wrong when two bytes are left over: the third character of "XYZ=" holds
// the byte's low four bits unshifted (b & 0x0f, not (b << 2) & 0x3c), so a decoder reads 0xff as
// 0xf3. Every chunk here ends on a pixel (512 and the picture are whole pixels) and every pixel is
// opaque, so that byte is always an alpha of 255: right, the character is '8'; from the defect, 'P'.
// A 'P' there becomes '8'; a libchafa without the defect writes '8' and is left alone.
void mend_kitty_chunk_ends(std::string& sequences)
{
    constexpr std::string_view chunk_end = "P=\x1b\\";
    for (std::size_t at = sequences.find(chunk_end); at != std::string::npos; at = sequences.find(chunk_end, at + 1))
        sequences[at] = '8';
}

Diagnostic chafa_failure(std::string reason) { return Diagnostic{"libchafa", 0, std::move(reason)}; }

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// `pixels` (opaque RGBA rows, `width` x `height`) as the escape sequences of `protocol`, on cells of
// `cell` pixels; libchafa's failure named.
Expected<std::string> encode_rgba(const std::vector<std::uint8_t>& pixels, int width, int height, CellPixels cell,
                                       TerminalPictureProtocol protocol,
                                       SixelRegisters registers = SixelRegisters::true_colour)
{
    if (width <= 0 || height <= 0 || cell.width <= 0 || cell.height <= 0)
        return chafa_failure("no picture of " + size_text(width, height) + " pixels on cells of " +
                             size_text(cell.width, cell.height));
    const auto config = exact_config(width, height, cell, protocol, registers);
    const std::unique_ptr<ChafaCanvas, CanvasRelease> canvas(chafa_canvas_new(config.get()));
    if (!canvas)
        return chafa_failure("cannot make a canvas of " + size_text(width, height) + " pixels");
    chafa_canvas_draw_all_pixels(canvas.get(), CHAFA_PIXEL_RGBA8_UNASSOCIATED, pixels.data(), width, height,
                                 width * bytes_per_pixel);
    // No terminal's description: libchafa's fallback holds the sixel and kitty sequences.
    GString* printed = chafa_canvas_print(canvas.get(), nullptr);
    if (printed == nullptr)
        return chafa_failure("printed nothing for a canvas of " + size_text(width, height) + " pixels");
    std::string sequences(printed->str, printed->len);
    g_string_free(printed, TRUE);
    if (protocol == TerminalPictureProtocol::kitty)
        mend_kitty_chunk_ends(sequences);
    return sequences;
}

} // namespace

Expected<std::string> encode_terminal_picture(const Bitmap& bitmap, TerminalPictureProtocol protocol)
{
    const int height = png_rows(bitmap.height(), PngShape::monitor);
    Expected<std::string> sequences =
        encode_rgba(monitor_rgba(bitmap, height, raster_row_of_monitor), bitmap.width(), height,
                    {terminal_picture_cell_width, terminal_picture_cell_height}, protocol);
    if (sequences)
        *sequences += '\n';
    return sequences;
}

Expected<std::string> encode_picture_band(const Bitmap& picture, CellRowBand band, CellPixels cell,
                                          TerminalPictureProtocol protocol)
{
    if (cell.width <= 0 || cell.height <= 0 || band.first < 0 || band.end <= band.first ||
        band.end * cell.height > picture.height())
        return chafa_failure("cell rows " + std::to_string(band.first) + " to " + std::to_string(band.end) +
                             " of cells " + size_text(cell.width, cell.height) + " are not within a picture of " +
                             size_text(picture.width(), picture.height()) + " pixels");
    const int first_row = band.first * cell.height;
    const auto row_of = [first_row](int y) { return first_row + y; };
    const int height = (band.end - band.first) * cell.height;
    if (protocol == TerminalPictureProtocol::kitty)
        return encode_rgba(monitor_rgba(picture, height, row_of), picture.width(), height, cell, protocol);
    // libchafa makes a sixel picture's height a multiple of 6 (a sixel's height), scaling the
    // picture to fit: the band is sent that tall, its rows below the band transparent (left
    // unpainted, so what is under them stays), on "cells" of six rows so nothing is scaled.
    constexpr int sixel_rows = 6;
    const int sixel_height = cells_holding(height, sixel_rows) * sixel_rows;
    std::vector<std::uint8_t> pixels = monitor_rgba(picture, height, row_of);
    pixels.resize(static_cast<std::size_t>(picture.width()) * static_cast<std::size_t>(sixel_height) * bytes_per_pixel, 0);
    return encode_rgba(pixels, picture.width(), sixel_height, {cell.width, sixel_rows}, protocol,
                       SixelRegisters::white_and_black);
}

} // namespace apcs
