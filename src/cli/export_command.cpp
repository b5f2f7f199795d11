#include "apcs/cli/export_command.h"

#include "apcs/animation/memory_budget.h"
#include "fit_command.h"
#include "memory_limit.h"
#include "apcs/cli/path_command.h"
#include "report.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <variant>

namespace apcs {

ViewAngles export_view(const CommonOptions& options, bool all_z_zero)
{
    if (options.given.theta || options.given.phi || !all_z_zero)
        return options.view;
    for (const ViewPreset& preset : view_presets)
        if (std::string_view(preset.name) == "top")
            return preset.angles;
    return options.view;
}

namespace {

// The document's text, held whole until it is written: a control point's outline vertex, mark and
// waypoint come to about 650 bytes, a frame's waypoint to about 110, a vertex's waypoint in one
// frame of an animation to about 115 (measured on the documents of tests/e2e/sif_renders.sh).
constexpr std::uint64_t document_bytes_per_point = 900; // with the circle's waypoints copied once
constexpr std::uint64_t document_bytes_per_frame = 160;
constexpr std::uint64_t document_bytes_per_vertex_frame = 160;

bool z_all_zero(std::span<const Vec3> points)
{
    return std::ranges::all_of(points, [](const Vec3& point) { return point.z == 0.0; });
}

ExitStatus write_document(const std::string& document, const ExportRequest& request, const CommonOptions& options,
                          std::ostream& out, std::ostream& err)
{
    if (Expected<void> written = write_picture_bytes(request.sif, document, read_files_guard(options), out); !written)
        return report_bad_input(written.error(), err);
    return ExitStatus::success;
}

// The frames a --sif-motion frames document moves through: KEY1, the in-betweens, KEY2.
std::vector<Vec3> path_frames(const ControlPoints& points, const EvaluatedPath& path)
{
    std::vector<Vec3> frames{points.front().position};
    for (const Inbetween& inbetween : path.inbetweens)
        frames.push_back(inbetween.position);
    frames.push_back(points.back().position);
    return frames;
}

ExitStatus export_path(const ExportRequest& request, const CommonOptions& options, std::ostream& out,
                       std::ostream& err)
{
    const std::filesystem::path& file = request.files.front();
    const Expected<DatFile> dat = read_dat_file(file);
    if (!dat)
        return report_bad_input(dat.error(), err);
    const ControlPoints points = control_points_from(*dat, options.staff);
    const bool frames = request.motion == SifMotion::frames;
    // A TCB document evaluates no samples: only --sif-motion frames samples the curve.
    const memory::PathRequest budget{points.size(), frames ? options.path.samples_per_segment : 1,
                                     frames ? options.path.inbetween_count : 0, false};
    const std::uint64_t frame_count = frames ? static_cast<std::uint64_t>(options.path.inbetween_count) + 2 : 0;
    const std::uint64_t document_bytes = points.size() * document_bytes_per_point + frame_count * document_bytes_per_frame;
    const std::string asked = frames ? memory::describe(budget) : std::to_string(points.size()) + " control points";
    if (const auto refused = refuse_over_budget(asked + " and their Synfig document",
                                                memory::saturating_sum(memory::path_bytes(budget), document_bytes), options,
                                                frames ? "lower --samples or --inbetweens" : "export a shorter path",
                                                err))
        return *refused;
    const PathSettings settings = settings_of_path(*dat, options);
    std::vector<Vec3> frame_positions;
    if (frames) {
        const EvaluatedPath path = evaluate_path(points, settings);
        warn_if_frames_freeze(path, file.string(), err);
        frame_positions = path_frames(points, path);
    }
    // The view is chosen on the control points themselves, not on a copy of their positions.
    const bool flat = std::ranges::all_of(points, [](const ControlPoint& point) { return point.position.z == 0.0; });
    const SifPathRequest document{points,  settings.slopes, export_view(options, flat),
                                  request.timing, request.motion, frame_positions, file.filename().string()};
    if (!frames)
        for (const std::string& sentence : sif_left_out(points, settings.slopes))
            err << "apcs: " << file.string() << ": not carried to Synfig: " << sentence
                << " (--sif-motion frames keeps it)\n";
    return write_document(sif_path_document(document), request, options, out, err);
}

ExitStatus export_animation(const ExportRequest& request, const CommonOptions& options, std::ostream& out,
                            std::ostream& err)
{
    const FitFiles files{request.files[0], request.files[1], request.files[2], request.files[3]};
    std::variant<FittedAnimation, ExitStatus> fitted = fit_all_frames(files, options, err, document_bytes_per_vertex_frame);
    if (const ExitStatus* failed = std::get_if<ExitStatus>(&fitted))
        return *failed;
    const FittedAnimation& animation = std::get<FittedAnimation>(fitted);
    bool flat = true;
    for (std::size_t f = 0; f < animation.frames.frame_count() && flat; ++f)
        flat = z_all_zero(animation.frames.frame(f));
    const SifAnimationRequest document{animation.keys.key1, animation.frames, export_view(options, flat),
                                       request.timing.fps, files.key1.filename().string() + " to " +
                                                               files.key2.filename().string()};
    return write_document(sif_animation_document(document), request, options, out, err);
}

} // namespace

ExitStatus run_export_command(const ExportRequest& request, const CommonOptions& options, std::ostream& out,
                              std::ostream& err)
{
    if (request.sif != standard_stream_name && read_files_guard(options).guards(request.sif))
        return report_bad_input(
            Diagnostic{request.sif.string(), 0, "is an input of this run; --sif never writes over an input"}, err);
    return request.files.size() == 1 ? export_path(request, options, out, err)
                                     : export_animation(request, options, out, err);
}

} // namespace apcs
