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

// The monitor's picture as opaque RGBA rows: lit pixels white, the others black.
std::vector<std::uint8_t> monitor_rgba(const Bitmap& bitmap)
{
    const int rows = png_rows(bitmap.height(), PngShape::monitor);
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(bitmap.width()) * static_cast<std::size_t>(rows) *
                                     bytes_per_pixel);
    std::size_t at = 0;
    for (int y = 0; y < rows; ++y) {
        const int source = raster_row_of(y, PngShape::monitor);
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

int cells_holding(int pixels, int cell) { return (pixels + cell - 1) / cell; }

struct ConfigRelease {
    void operator()(ChafaCanvasConfig* config) const { chafa_canvas_config_unref(config); }
};
struct CanvasRelease {
    void operator()(ChafaCanvas* canvas) const { chafa_canvas_unref(canvas); }
};

// libchafa's configuration for an exact picture: true colour (black and white are palette entries
// as they are), no dithering, the cells a picture of `width` x `height` pixels fills.
std::unique_ptr<ChafaCanvasConfig, ConfigRelease> exact_config(int width, int height,
                                                               TerminalPictureProtocol protocol)
{
    std::unique_ptr<ChafaCanvasConfig, ConfigRelease> config(chafa_canvas_config_new());
    chafa_canvas_config_set_pixel_mode(config.get(), protocol == TerminalPictureProtocol::sixel
                                                         ? CHAFA_PIXEL_MODE_SIXELS
                                                         : CHAFA_PIXEL_MODE_KITTY);
    chafa_canvas_config_set_canvas_mode(config.get(), CHAFA_CANVAS_MODE_TRUECOLOR);
    chafa_canvas_config_set_dither_mode(config.get(), CHAFA_DITHER_MODE_NONE);
    chafa_canvas_config_set_cell_geometry(config.get(), terminal_picture_cell_width, terminal_picture_cell_height);
    chafa_canvas_config_set_geometry(config.get(), cells_holding(width, terminal_picture_cell_width),
                                     cells_holding(height, terminal_picture_cell_height));
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

} // namespace

std::optional<std::string> encode_terminal_picture(const Bitmap& bitmap, TerminalPictureProtocol protocol)
{
    const int width = bitmap.width();
    const int height = png_rows(bitmap.height(), PngShape::monitor);
    if (width <= 0 || height <= 0)
        return std::nullopt;
    const std::vector<std::uint8_t> pixels = monitor_rgba(bitmap);
    const auto config = exact_config(width, height, protocol);
    const std::unique_ptr<ChafaCanvas, CanvasRelease> canvas(chafa_canvas_new(config.get()));
    if (!canvas)
        return std::nullopt;
    chafa_canvas_draw_all_pixels(canvas.get(), CHAFA_PIXEL_RGBA8_UNASSOCIATED, pixels.data(), width, height,
                                 width * bytes_per_pixel);
    // No terminal's description: libchafa's fallback holds the sixel and kitty sequences.
    GString* printed = chafa_canvas_print(canvas.get(), nullptr);
    if (printed == nullptr)
        return std::nullopt;
    std::string sequences(printed->str, printed->len);
    g_string_free(printed, TRUE);
    if (protocol == TerminalPictureProtocol::kitty)
        mend_kitty_chunk_ends(sequences);
    sequences += '\n';
    return sequences;
}

} // namespace apcs
