#pragma once

#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/session/session_model.h"

#include <string>

namespace apcs {

// The picture as a PNG file of `shape`, through the session's files; the message line says
// what happened, and the log gets `log_line` when it is written.
void write_picture(StepContext& context, const std::string& name, const GraphicsScreen& picture, PngShape shape,
                   const std::string& log_line);

// `bytes` (an encoded picture) as the file `name`, said and logged as write_picture does.
void store_picture(StepContext& context, const std::string& name, const std::string& bytes,
                   const std::string& log_line);

} // namespace apcs
