#include "apcs/cli/report.h"

#include <ostream>

namespace apcs {

ExitStatus report_bad_input(const Diagnostic& problem, std::ostream& err)
{
    err << problem.to_string() << '\n';
    return ExitStatus::bad_input;
}

void warn_if_frames_freeze(const EvaluatedPath& path, int inbetween_count, std::ostream& err)
{
    if (path.frames_freeze)
        err << "apcs: " << inbetween_count << " in-betweens from " << path.curve.sample_count() - 1
            << " curve samples: frames will freeze\n";
}

} // namespace apcs
