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
#include <string_view>

namespace apcs {

// `# curve` (every sample) then `# inbetweens` (SPEC §4.3, §7.4).
std::string format_path_print(const EvaluatedPath& path);

// The name "-": standard input where a file is read, standard output where one is written.
inline constexpr std::string_view standard_stream_name = "-";

// A picture's bytes to `target` atomically, or to `out` when `target` is "-".
[[nodiscard]] std::optional<Diagnostic> write_picture_bytes(const std::filesystem::path& target, const std::string& bytes,
                                                            std::ostream& out);

// Writes the screen's raster (text drawn in the font) as a PNG, atomically; to `out` when
// `target` is "-".
[[nodiscard]] std::optional<Diagnostic> write_png_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                                                       PngShape shape, std::ostream& out);

// Writes the screen as an SVG (encode_svg), atomically; to `out` when `target` is "-".
[[nodiscard]] std::optional<Diagnostic> write_svg_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                                                       std::ostream& out);

// Every picture `options` asks for (--png, --png-raw, --svg) of `screen`; the first problem.
[[nodiscard]] std::optional<Diagnostic> write_pictures(const GraphicsScreen& screen, const CommonOptions& options,
                                                       std::ostream& out);

// The path screen of `apcs path --png`: curve, control points, in-betweens, the staff showing the
// first control point's values.
GraphicsScreen draw_path_file_screen(const ControlPoints& points, const EvaluatedPath& path, ViewAngles angles);

// `apcs path FILE`: prints (--print, the default) or draws (--png) one point's path.
ExitStatus run_path_command(const std::filesystem::path& file, const CommonOptions& options, std::ostream& out,
                            std::ostream& err);

} // namespace apcs
