#include "fit_command.h"

#include "apcs/animation/add_points.h"
#include "apcs/animation/surface_fit.h"
#include "apcs/animation/memory_budget.h"
#include "frame_output.h"
#include "memory_limit.h"
#include "apcs/cli/path_command.h"
#include "report.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/path_files.h"

#include <array>
#include <future>
#include <optional>
#include <string>
#include <ostream>
#include <utility>
#include <variant>

namespace apcs {

namespace {

// Only --print and the pictures need every frame at once; in-between files alone are streamed.
bool all_frames_needed(const CommonOptions& options) { return options.print || pictures_asked(options); }

// Surface fitting holds M + 2 frames of every point when all frames are needed, else only the
// keys, and both edge paths while it fits.
std::optional<ExitStatus> refuse_over_budget_of_fit(const EqualisedKeys& keys, const ControlPoints& first,
                                                    const ControlPoints& last, const CommonOptions& options,
                                                    bool all_frames, std::ostream& err,
                                                    std::uint64_t more_bytes_per_frame_point = 0)
{
    const std::size_t frames_held =
        all_frames ? static_cast<std::size_t>(options.path.inbetween_count) + 2 : 2;
    const memory::FramesRequest frames{frames_held, keys.key1.point_count(), options.print};
    const auto path = [&options](const ControlPoints& points) {
        return memory::path_bytes({points.size(), options.path.samples_per_segment, options.path.inbetween_count, false});
    };
    // At most 100002 frames of 2·10^6 points (SPEC §2.1's limits, doubled by adding points) and a
    // few hundred bytes each: far from wrapping.
    const std::uint64_t more = static_cast<std::uint64_t>(frames_held) * keys.key1.point_count() * more_bytes_per_frame_point;
    const std::uint64_t needed = memory::saturating_sum(memory::saturating_sum(memory::frames_bytes(frames), more),
                                                        memory::saturating_sum(path(first), path(last)));
    const std::string inbetweens = "(--inbetweens " + std::to_string(options.path.inbetween_count) + ")";
    const std::string asked = all_frames
                                  ? memory::describe(frames) + " " + inbetweens + " and their paths"
                                  : "the key frames (" + memory::describe(frames) +
                                        "), the in-betweens made one at a time " + inbetweens + ", and their paths";
    return refuse_over_budget(asked, needed, options, "lower --inbetweens or --samples, or use key frames of fewer points",
                              err);
}

// Both edge paths evaluated, with the "frames will freeze" warning of each that is used.
std::pair<EvaluatedPath, EvaluatedPath> evaluate_both_paths(const FitInputs& inputs, const FitFiles& files,
                                                            std::ostream& err)
{
    EvaluatedPath first_path = evaluate_path(inputs.first, inputs.first_settings);
    EvaluatedPath last_path = evaluate_path(inputs.last, inputs.last_settings);
    warn_if_frames_freeze(first_path, files.path_first.string(), err);
    if (!inputs.keys.key1.is_closed())
        warn_if_frames_freeze(last_path, files.path_last.string(), err);
    return {std::move(first_path), std::move(last_path)};
}

} // namespace

std::variant<FitInputs, ExitStatus> read_fit_inputs(const FitFiles& files, const CommonOptions& options,
                                                    std::ostream& err)
{
    // The keys are read side by side, one per core: for large keys reading is much of the work.
    std::future<Expected<Graphic>> reading_key2 = std::async(std::launch::async, read_key_frame, files.key2);
    Expected<Graphic> key1 = read_key_frame(files.key1);
    Expected<Graphic> key2 = reading_key2.get();
    if (!key1)
        return report_bad_input(key1.error(), err);
    if (!key2)
        return report_bad_input(key2.error(), err);
    EqualisedKeys keys = equalise_key_frames(std::move(*key1), std::move(*key2));

    Expected<DatFile> first_file = read_dat_file(files.path_first);
    if (!first_file)
        return report_bad_input(first_file.error(), err);
    Expected<ControlPoints> first =
        point_path_from(*first_file, files.path_first.string(), PathEnd::first, keys, options.staff);
    if (!first)
        return report_bad_input(first.error(), err);
    Expected<DatFile> last_file = read_dat_file(files.path_last);
    if (!last_file)
        return report_bad_input(last_file.error(), err);
    // A closed graphic needs one path only: the second is read but not used.
    Expected<ControlPoints> last =
        keys.key1.is_closed()
            ? Expected<ControlPoints>(control_points_from(*last_file, options.staff))
            : point_path_from(*last_file, files.path_last.string(), PathEnd::last, keys, options.staff);
    if (!last)
        return report_bad_input(last.error(), err);
    return FitInputs{std::move(keys), std::move(*first), std::move(*last), settings_of_path(*first_file, options),
                     settings_of_path(*last_file, options)};
}

std::variant<FittedAnimation, ExitStatus> fit_all_frames(const FitFiles& files, const CommonOptions& options,
                                                         std::ostream& err, std::uint64_t more_bytes_per_frame_point)
{
    std::variant<FitInputs, ExitStatus> read = read_fit_inputs(files, options, err);
    if (const ExitStatus* failed = std::get_if<ExitStatus>(&read))
        return *failed;
    FitInputs& inputs = std::get<FitInputs>(read);
    if (const auto refused = refuse_over_budget_of_fit(inputs.keys, inputs.first, inputs.last, options, true, err,
                                                       more_bytes_per_frame_point))
        return *refused;
    const auto [first_path, last_path] = evaluate_both_paths(inputs, files, err);
    FrameSequence frames = fit_key_frames(inputs.keys, first_path, last_path, options.surface);
    return FittedAnimation{std::move(inputs.keys), std::move(frames)};
}

ExitStatus run_fit_command(const FitFiles& files, const CommonOptions& options, std::ostream& out, std::ostream& err)
{
    const std::array<std::filesystem::path, 2> key_files{files.key1, files.key2};
    if (all_frames_needed(options)) {
        std::variant<FittedAnimation, ExitStatus> fitted = fit_all_frames(files, options, err);
        if (const ExitStatus* failed = std::get_if<ExitStatus>(&fitted))
            return *failed;
        const FittedAnimation& animation = std::get<FittedAnimation>(fitted);
        return deliver_frames(animation.frames, animation.keys.key1, options, key_files, out, err);
    }
    std::variant<FitInputs, ExitStatus> read = read_fit_inputs(files, options, err);
    if (const ExitStatus* failed = std::get_if<ExitStatus>(&read))
        return *failed;
    const FitInputs& inputs = std::get<FitInputs>(read);
    if (const auto refused = refuse_over_budget_of_fit(inputs.keys, inputs.first, inputs.last, options, false, err))
        return *refused;
    const auto [first_path, last_path] = evaluate_both_paths(inputs, files, err);
    // Each in-between is made, formatted and written a chunk at a time, a file per core.
    std::array<std::vector<Vec3>, 2> storage;
    const SurfaceFitter fitter = key_frames_fitter(inputs.keys, first_path, last_path, storage, options.surface);
    return deliver_inbetween_files(
        [&](const std::filesystem::path& folder, const KeyFileGuard& guard, const WriteProgress& progress) {
            return write_inbetween_files(fitter, inputs.keys.key1, folder, guard, progress);
        },
        options, key_files, err);
}

} // namespace apcs
