#include "report.h"

#include "apcs/base/utf8.h"

#include <ostream>

namespace apcs {

ExitStatus report_bad_input(const Diagnostic& problem, std::ostream& err)
{
    err << problem.to_string() << '\n';
    return ExitStatus::bad_input;
}

void warn_if_frames_freeze(const EvaluatedPath& path, const std::string& file, std::ostream& err)
{
    if (!path.frames_freeze())
        return;
    err << "apcs: " << escape_controls(file) << ": frames will freeze at " << describe_frozen_frames(path, 8);
    const std::size_t intervals = path.curve.sample_count() - 1;
    if (path.inbetweens.size() > intervals)
        err << " (" << path.inbetweens.size() << " in-betweens, " << intervals << " curve samples)";
    err << '\n';
}

} // namespace apcs
