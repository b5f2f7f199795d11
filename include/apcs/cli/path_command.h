#pragma once

#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"
#include "apcs/formats/dat_file.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/raster/terminal_picture.h"

#include <array>
#include <filesystem>
#include <utility>
#include <span>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

// The path settings of a path file (SPEC §2.1): --slopes where given, else the file's SLOPES line,
// else the default 1 1.
PathSettings settings_of_path(const DatFile& file, const CommonOptions& options);

// `# curve` (every sample) then `# inbetweens` (SPEC §4.3, §7.4).
std::string format_path_print(const EvaluatedPath& path);

// The name "-": standard input where a file is read, standard output where one is written.
inline constexpr std::string_view standard_stream_name = "-";

// The files of options.read_files, guarded: a picture's backup goes to NAME.b01 … rather than
// replace one of them (write_file_atomically).
KeyFileGuard read_files_guard(const CommonOptions& options);

// A picture's bytes to `target` atomically, or to `out` when `target` is "-". An old picture is
// kept as NAME.bak, or as NAME.b01 … when NAME.bak is one of `inputs`.
Expected<void> write_picture_bytes(const std::filesystem::path& target, const std::string& bytes,
                                   const KeyFileGuard& inputs, std::ostream& out);

// Writes the screen's raster (text drawn in the font) as a PNG, atomically; to `out` when
// `target` is "-". The old picture's backup never replaces one of `inputs`.
Expected<void> write_png_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                              PngShape shape, const KeyFileGuard& inputs, std::ostream& out,
                              PngInk ink = PngInk::monitor);

// Writes the screen as an SVG (encode_svg), atomically; to `out` when `target` is "-". The old
// picture's backup never replaces one of `inputs`.
Expected<void> write_svg_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                              const KeyFileGuard& inputs, std::ostream& out);

// Writes the screen's raster as the escape sequences of a terminal picture (encode_terminal_picture),
// atomically; to `out` when `target` is "-". The old picture's backup never replaces one of `inputs`.
Expected<void> write_terminal_picture_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                                           TerminalPictureProtocol protocol, const KeyFileGuard& inputs,
                                           std::ostream& out);

// The picture options and where each writes: --png, --png-raw, --svg, --gif, --sixel, --kitty.
std::array<std::pair<const char*, const std::optional<std::filesystem::path>*>, 6>
picture_targets(const CommonOptions& options);

// ok unless a picture option names one of `inputs` (through a link, in another case, without an
// extension); then "TARGET: is an input of this run; --png never writes over an input".
Expected<void> check_pictures_spare_inputs(const CommonOptions& options, std::span<const std::filesystem::path> inputs);

// Every still picture `options` asks for (--png, --png-raw, --svg, --sixel, --kitty) of `screen`, no
// backup replacing one of options.read_files; the first problem.
Expected<void> write_pictures(const GraphicsScreen& screen, const CommonOptions& options, std::ostream& out);

// The path screen of `apcs path --png`: curve, control points, in-betweens, the staff showing the
// first control point's values.
GraphicsScreen draw_path_file_screen(const ControlPoints& points, const EvaluatedPath& path, ViewAngles angles);

// A path file: a .dat file, or a Synfig document (.sif) whose animated vector `sif_param` is read
// into the plane of options.view (SPEC §7.5), its warnings written to `err`.
Expected<DatFile> read_path_input(const std::filesystem::path& file, const CommonOptions& options,
                                  const std::string& sif_param, std::ostream& err);

// `apcs path FILE`: prints (--print, the default) or draws (--png) one point's path.
ExitStatus run_path_command(const std::filesystem::path& file, const CommonOptions& options,
                            const std::string& sif_param, std::ostream& out, std::ostream& err);

} // namespace apcs
