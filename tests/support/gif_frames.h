#pragma once

#include <gif_lib.h>

#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace apcs::test {

// A GIF read back with giflib (DGifSlurp): its frames' sizes, delays and pixels, and whether it loops.
struct GifFrames {
    int width = 0;
    int height = 0;
    bool loops = false;
    struct Frame {
        int width = 0;
        int height = 0;
        int delay_centiseconds = -1;
        std::vector<unsigned char> pixels; // palette indices, row by row
    };
    std::vector<Frame> frames;
    std::vector<GifColorType> palette;
};

inline std::optional<GifFrames> read_gif(const std::string& bytes)
{
    struct Source {
        const std::string* bytes;
        std::size_t at = 0;
    } source{&bytes};
    const InputFunc read = [](GifFileType* gif, GifByteType* into, int wanted) {
        auto* from = static_cast<Source*>(gif->UserData);
        const std::size_t count = std::min(static_cast<std::size_t>(wanted), from->bytes->size() - from->at);
        std::memcpy(into, from->bytes->data() + from->at, count);
        from->at += count;
        return static_cast<int>(count);
    };
    int error = 0;
    GifFileType* gif = DGifOpen(&source, read, &error);
    if (gif == nullptr)
        return std::nullopt;
    std::optional<GifFrames> result;
    if (DGifSlurp(gif) == GIF_OK) {
        result.emplace();
        result->width = gif->SWidth;
        result->height = gif->SHeight;
        if (gif->SColorMap != nullptr)
            result->palette.assign(gif->SColorMap->Colors, gif->SColorMap->Colors + gif->SColorMap->ColorCount);
        // DGifSlurp keeps the extensions before an image with that image.
        if (gif->ImageCount > 0)
            for (int k = 0; k < gif->SavedImages[0].ExtensionBlockCount; ++k) {
                const ExtensionBlock& block = gif->SavedImages[0].ExtensionBlocks[k];
                if (block.Function == APPLICATION_EXT_FUNC_CODE && block.ByteCount == 11 &&
                    std::memcmp(block.Bytes, "NETSCAPE2.0", 11) == 0)
                    result->loops = true;
            }
        for (int k = 0; k < gif->ImageCount; ++k) {
            const SavedImage& image = gif->SavedImages[k];
            GifFrames::Frame frame;
            frame.width = image.ImageDesc.Width;
            frame.height = image.ImageDesc.Height;
            GraphicsControlBlock control;
            if (DGifSavedExtensionToGCB(gif, k, &control) == GIF_OK)
                frame.delay_centiseconds = control.DelayTime;
            frame.pixels.assign(image.RasterBits, image.RasterBits + frame.width * frame.height);
            result->frames.push_back(std::move(frame));
        }
    }
    DGifCloseFile(gif, &error);
    return result;
}

} // namespace apcs::test
