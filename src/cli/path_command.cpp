#include "apcs/cli/path_command.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/print_format.h"

#include <ostream>

namespace apcs {

ControlPoints control_points_from(const DatFile& file, const StaffValues& defaults)
{
    ControlPoints points;
    points.reserve(file.point_count());
    for (const DatPart& part : file.parts)
        for (const DatPoint& point : part.points)
            points.push_back({point.position, point.staff.value_or(defaults)});
    return points;
}

std::string format_path_print(const EvaluatedPath& path)
{
    std::string text;
    append_print_section(text, "curve", path.curve.points);
    text += "# inbetweens\n";
    for (const Inbetween& inbetween : path.inbetweens)
        append_print_point(text, inbetween.position);
    return text;
}

ExitStatus run_path_command(const std::filesystem::path& file, const CommonOptions& options, std::ostream& out,
                            std::ostream& err)
{
    const Expected<DatFile> dat = read_dat_file(file);
    if (!dat) {
        err << dat.error().to_string() << '\n';
        return ExitStatus::bad_input;
    }
    const ControlPoints points = control_points_from(*dat, options.staff);
    const EvaluatedPath path = evaluate_path(points, options.path);
    if (path.frames_freeze)
        err << "apcs: " << options.path.inbetween_count << " in-betweens from " << path.curve.points.size() - 1
            << " curve samples: frames will freeze\n";
    if (options.print || !options.png) {
        const std::string text = format_path_print(path);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
    return ExitStatus::success;
}

} // namespace apcs
