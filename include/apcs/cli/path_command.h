#pragma once

#include "apcs/session/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/formats/dat_file.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/png_encoder.h"

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

namespace apcs {

// `# curve` (every sample) then `# inbetweens` (SPEC §4.3, §7.4).
std::string format_path_print(const EvaluatedPath& path);

// Writes the screen's raster (text drawn in the font) as a PNG, atomically.
[[nodiscard]] std::optional<Diagnostic> write_png_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                                                       PngShape shape);

// The path screen of `apcs path --png`: curve, control points, in-betweens, the staff showing the
// first control point's values.
GraphicsScreen draw_path_file_screen(const ControlPoints& points, const EvaluatedPath& path, ViewAngles angles);

// `apcs path FILE`: prints (--print, the default) or draws (--png) one point's path.
ExitStatus run_path_command(const std::filesystem::path& file, const CommonOptions& options, std::ostream& out,
                            std::ostream& err);

} // namespace apcs
