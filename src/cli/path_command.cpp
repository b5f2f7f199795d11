#include "apcs/cli/path_command.h"

#include "apcs/animation/memory_budget.h"
#include "memory_limit.h"
#include "report.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/print_format.h"
#include "apcs/formats/sif_path.h"
#include "apcs/raster/png_encoder.h"
#include "apcs/raster/svg_encoder.h"
#include "apcs/screens/path_screen.h"
#include "apcs/raster/screen_layout.h"

#include <ostream>
#include <utility>

namespace apcs {

std::string format_path_print(const EvaluatedPath& path)
{
    std::string text;
    append_print_section(text, "curve", path.curve.samples());
    text += "# inbetweens\n";
    for (const Inbetween& inbetween : path.inbetweens)
        append_print_point(text, inbetween.position);
    return text;
}

namespace {

// `inputs` guarded, standard input ("-") and empty names left out.
KeyFileGuard guard_of(std::span<const std::filesystem::path> inputs)
{
    KeyFileGuard guard;
    for (const std::filesystem::path& input : inputs)
        if (!input.empty() && input != standard_stream_name)
            guard.protect(input);
    return guard;
}

} // namespace

KeyFileGuard read_files_guard(const CommonOptions& options) { return guard_of(options.read_files); }

Expected<void> write_picture_bytes(const std::filesystem::path& target, const std::string& bytes,
                                   const KeyFileGuard& inputs, std::ostream& out)
{
    if (target == standard_stream_name) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return ok;
    }
    const Expected<WriteResult> written = write_file_atomically(target, bytes, &inputs);
    if (!written)
        return written.error();
    return ok;
}

Expected<void> write_png_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                              PngShape shape, const KeyFileGuard& inputs, std::ostream& out, PngInk ink)
{
    const Expected<std::string> png = encode_png(render_raster(screen), shape, ink);
    if (!png)
        return Diagnostic{target.string(), 0, "cannot encode the PNG image: " + png.error().to_string()};
    return write_picture_bytes(target, *png, inputs, out);
}

Expected<void> write_svg_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                              const KeyFileGuard& inputs, std::ostream& out)
{
    return write_picture_bytes(target, encode_svg(screen), inputs, out);
}

Expected<void> write_terminal_picture_file(const std::filesystem::path& target, const GraphicsScreen& screen,
                                           TerminalPictureProtocol protocol, const KeyFileGuard& inputs,
                                           std::ostream& out)
{
    const Expected<std::string> picture = encode_terminal_picture(render_raster(screen), protocol);
    if (!picture)
        return Diagnostic{target.string(), 0,
                          std::string(protocol == TerminalPictureProtocol::sixel ? "cannot encode the sixel picture: "
                                                                                 : "cannot encode the kitty picture: ") +
                              picture.error().to_string()};
    return write_picture_bytes(target, *picture, inputs, out);
}

std::array<std::pair<const char*, const std::optional<std::filesystem::path>*>, 6>
picture_targets(const CommonOptions& options)
{
    return {{{"--png", &options.png},
             {"--png-raw", &options.png_raw},
             {"--svg", &options.svg},
             {"--gif", &options.gif},
             {"--sixel", &options.sixel},
             {"--kitty", &options.kitty}}};
}

Expected<void> check_pictures_spare_inputs(const CommonOptions& options, std::span<const std::filesystem::path> inputs)
{
    const std::filesystem::path dash(standard_stream_name);
    const KeyFileGuard read = guard_of(inputs);
    for (const auto& [option, target] : picture_targets(options))
        if (*target && **target != dash && read.guards(**target))
            return Diagnostic{(*target)->string(), 0, "is an input of this run; " + std::string(option) +
                                                          " never writes over an input"};
    return ok;
}

Expected<void> write_pictures(const GraphicsScreen& screen, const CommonOptions& options, std::ostream& out)
{
    const KeyFileGuard inputs = read_files_guard(options);
    for (const auto& [target, shape] : {std::pair{options.png, PngShape::monitor}, std::pair{options.png_raw, PngShape::raw}})
        if (target)
            if (auto outcome = write_png_file(*target, screen, shape, inputs, out); !outcome)
                return outcome.error();
    for (const auto& [target, protocol] : {std::pair{options.sixel, TerminalPictureProtocol::sixel},
                                           std::pair{options.kitty, TerminalPictureProtocol::kitty}})
        if (target)
            if (auto outcome = write_terminal_picture_file(*target, screen, protocol, inputs, out); !outcome)
                return outcome.error();
    if (options.svg)
        return write_svg_file(*options.svg, screen, inputs, out);
    return ok;
}

GraphicsScreen draw_path_file_screen(const ControlPoints& points, const EvaluatedPath& path, ViewAngles angles)
{
    const PathScreenContent content = path_screen_content(points, path);
    // The path screen's view, filled with the path as the editor's is (SPEC §7.2.1).
    return draw_path_screen(content, path_screen_scene(content).fill(angles, layout::view_area));
}

PathSettings settings_of_path(const DatFile& file, const CommonOptions& options)
{
    PathSettings settings = options.path;
    if (!options.given.slopes && file.slopes)
        settings.slopes = *file.slopes;
    return settings;
}

Expected<DatFile> read_path_input(const std::filesystem::path& file, const CommonOptions& options,
                                  const std::string& sif_param, std::ostream& err)
{
    if (!is_sif_name(file.string()))
        return read_dat_file(file);
    const Expected<std::string> text = read_text_file(file);
    if (!text)
        return text.error();
    Expected<SifPath> read = parse_sif_path(
        *text, file.string(), {sif_param, sif_plane_of(options.view.theta_degrees, options.view.phi_degrees)});
    if (!read)
        return read.error();
    for (const std::string& warning : read->warnings)
        err << "apcs: warning: " << warning << '\n';
    return std::move(read->file);
}

ExitStatus run_path_command(const std::filesystem::path& file, const CommonOptions& options,
                            const std::string& sif_param, std::ostream& out, std::ostream& err)
{
    const Expected<DatFile> dat = read_path_input(file, options, sif_param, err);
    if (!dat)
        return report_bad_input(dat.error(), err);
    const ControlPoints points = control_points_from(*dat, options.staff);
    const memory::PathRequest request{points.size(), options.path.samples_per_segment, options.path.inbetween_count,
                                      options.print || !pictures_asked(options)};
    if (const auto refused = refuse_over_budget(memory::describe(request), memory::path_bytes(request), options,
                                                "lower --samples or --inbetweens", err))
        return *refused;
    const EvaluatedPath path = evaluate_path(points, settings_of_path(*dat, options));
    warn_if_frames_freeze(path, file.string(), err);
    if (pictures_asked(options))
        if (Expected<void> written = write_pictures(draw_path_file_screen(points, path, options.view), options, out);
            !written)
            return report_bad_input(written.error(), err);
    if (options.print || !pictures_asked(options)) {
        const std::string text = format_path_print(path);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
    return ExitStatus::success;
}

} // namespace apcs
