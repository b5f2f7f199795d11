#include "apcs/cli/fit_command.h"

#include "apcs/animation/add_points.h"
#include "apcs/animation/surface_fit.h"
#include "apcs/cli/frame_output.h"
#include "apcs/cli/path_command.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"

#include <array>
#include <ostream>

namespace apcs {

namespace {

ExitStatus report(const Diagnostic& problem, std::ostream& err)
{
    err << problem.to_string() << '\n';
    return ExitStatus::bad_input;
}

} // namespace

ExitStatus run_fit_command(const FitFiles& files, const CommonOptions& options, std::ostream& out, std::ostream& err)
{
    Expected<Graphic> key1 = read_key_frame(files.key1);
    if (!key1)
        return report(key1.error(), err);
    Expected<Graphic> key2 = read_key_frame(files.key2);
    if (!key2)
        return report(key2.error(), err);
    const EqualisedKeys keys = equalise_key_frames(std::move(*key1), std::move(*key2));
    const std::vector<Vec3> points1 = keys.key1.all_points();
    const std::vector<Vec3> points2 = keys.key2.all_points();

    const Expected<DatFile> first = read_dat_file(files.path_first);
    if (!first)
        return report(first.error(), err);
    if (auto problem = check_path_ends(*first, files.path_first.string(), "first", points1.front(), points2.front()))
        return report(*problem, err);
    const Expected<DatFile> last = read_dat_file(files.path_last);
    if (!last)
        return report(last.error(), err);
    // A closed graphic needs one path only: the second is read but not used.
    if (!keys.key1.is_closed())
        if (auto problem = check_path_ends(*last, files.path_last.string(), "last", points1.back(), points2.back()))
            return report(*problem, err);

    const EvaluatedPath first_path = evaluate_path(control_points_from(*first, options.staff), options.path);
    const EvaluatedPath last_path = evaluate_path(control_points_from(*last, options.staff), options.path);
    if (first_path.frames_freeze)
        err << "apcs: " << options.path.inbetween_count << " in-betweens from " << first_path.curve.points.size() - 1
            << " curve samples: frames will freeze\n";
    const FrameSequence frames = fit_key_frames(keys, first_path, last_path);

    const std::array<std::filesystem::path, 2> key_files{files.key1, files.key2};
    return deliver_frames(frames, keys.key1, options, key_files, out, err);
}

} // namespace apcs
