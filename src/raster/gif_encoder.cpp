#include "apcs/raster/gif_encoder.h"

#include "apcs/raster/png_encoder.h"

#include <gif_lib.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace apcs {

namespace {

int append_to_string(GifFileType* gif, const GifByteType* data, int length)
{
    static_cast<std::string*>(gif->UserData)->append(reinterpret_cast<const char*>(data), static_cast<std::size_t>(length));
    return length;
}

struct GifCloser {
    void operator()(GifFileType* gif) const
    {
        int error = 0;
        EGifCloseFile(gif, &error);
    }
};
using GifWriter = std::unique_ptr<GifFileType, GifCloser>;

struct MapFreer {
    void operator()(ColorMapObject* map) const { GifFreeMapObject(map); }
};

bool put_looping(GifFileType* gif)
{
    static const GifByteType application[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
    static const GifByteType loop_forever[] = {1, 0, 0}; // sub-block 1, loop count 0 = forever
    return EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE) == GIF_OK &&
           EGifPutExtensionBlock(gif, sizeof application, application) == GIF_OK &&
           EGifPutExtensionBlock(gif, sizeof loop_forever, loop_forever) == GIF_OK &&
           EGifPutExtensionTrailer(gif) == GIF_OK;
}

bool put_frame(GifFileType* gif, const Bitmap& bitmap, int rows, int delay_centiseconds)
{
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSAL_UNSPECIFIED;
    control.UserInputFlag = false;
    control.DelayTime = delay_centiseconds;
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&control, extension);
    if (EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) != GIF_OK ||
        EGifPutImageDesc(gif, 0, 0, bitmap.width(), rows, false, nullptr) != GIF_OK)
        return false;
    std::vector<GifPixelType> line(static_cast<std::size_t>(bitmap.width()));
    for (int y = 0; y < rows; ++y) {
        const int source = raster_row_of(y, PngShape::monitor);
        for (int x = 0; x < bitmap.width(); ++x)
            line[static_cast<std::size_t>(x)] = bitmap.get(x, source) ? 1 : 0;
        if (EGifPutLine(gif, line.data(), bitmap.width()) != GIF_OK)
            return false;
    }
    return true;
}

// giflib's own words for its error code ("Failed to write to given file", "Not enough memory").
Diagnostic giflib_failure(int error)
{
    const char* text = GifErrorString(error);
    return Diagnostic{"", 0, text != nullptr ? text : "giflib error " + std::to_string(error)};
}

} // namespace

int gif_delay_centiseconds(int delay_ms)
{
    return std::max(1, static_cast<int>(std::lround(delay_ms / 10.0)));
}

Expected<std::string> encode_gif(std::size_t frame_count, const std::function<Bitmap(std::size_t)>& frame_at,
                                      int delay_centiseconds)
{
    if (frame_count == 0)
        return Diagnostic{"", 0, "there are no frames"};
    std::string output;
    int error = 0;
    GifWriter gif(EGifOpen(&output, append_to_string, &error));
    if (!gif)
        return giflib_failure(error);
    const GifColorType colours[] = {{0, 0, 0}, {255, 255, 255}};
    const std::unique_ptr<ColorMapObject, MapFreer> palette(GifMakeMapObject(2, colours));
    if (!palette)
        return Diagnostic{"", 0, "out of memory"};
    EGifSetGifVersion(gif.get(), true);
    for (std::size_t k = 0; k < frame_count; ++k) {
        const Bitmap bitmap = frame_at(k);
        const int rows = png_rows(bitmap.height(), PngShape::monitor);
        if (k == 0 && (EGifPutScreenDesc(gif.get(), bitmap.width(), rows, 1, 0, palette.get()) != GIF_OK ||
                       !put_looping(gif.get())))
            return giflib_failure(gif->Error);
        if (!put_frame(gif.get(), bitmap, rows, delay_centiseconds))
            return giflib_failure(gif->Error);
    }
    if (EGifCloseFile(gif.release(), &error) != GIF_OK)
        return giflib_failure(error);
    return output;
}

} // namespace apcs
