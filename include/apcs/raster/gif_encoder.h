#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/raster/bitmap.h"

#include <cstddef>
#include <functional>
#include <string>

namespace apcs {

// The GIF frame delay, in the format's hundredths of a second, of `delay_ms` milliseconds:
// rounded, at least 1 (viewers play a delay of 0 at their own speed).
int gif_delay_centiseconds(int delay_ms);

// An animated GIF's bytes (giflib): `frame_count` frames, frame k the bitmap `frame_at(k)` (asked
// for in order, 0 first, so that no more than one frame is held), each shown as the monitor showed
// it (720x522 for the 720x348 raster, rows 1.5 pixels tall, as PngShape::monitor), white on black
// in a two-colour palette, each `delay_centiseconds` long, looping forever (the NETSCAPE2.0
// extension). On a failure giflib's reason (the Diagnostic's message; no file or line).
Expected<std::string> encode_gif(std::size_t frame_count, const std::function<Bitmap(std::size_t)>& frame_at,
                                      int delay_centiseconds);

} // namespace apcs
