#pragma once

#include "apcs/raster/bitmap.h"

#include <optional>
#include <string>

namespace apcs {

// The bitmap as a PNG file's bytes (libpng): 8-bit greyscale, lit pixels white on black like the
// monitor. Empty on a libpng failure.
std::optional<std::string> encode_png(const Bitmap& bitmap);

} // namespace apcs
