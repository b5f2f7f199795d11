#pragma once

#include "apcs/animation/speed_law.h"
#include "apcs/animation/vector_inbetween.h"
#include "apcs/base/exit_status.h"
#include "apcs/cli/options.h"

#include <filesystem>
#include <iosfwd>
#include <optional>

namespace apcs {

struct InbetweenSettings {
    std::filesystem::path key1;
    std::filesystem::path key2;
    // T: frames 0 … T; when not given, --inbetweens + 1.
    std::optional<int> frame_intervals;
    SpeedLaw law = SpeedLaw::linear;
    Padding padding = Padding::apcs;
};

// `apcs inbetween KEY1 KEY2` (SPEC §6): pad, interpolate by the law, print or write the frames.
ExitStatus run_inbetween_command(const InbetweenSettings& settings, const CommonOptions& options, std::ostream& out,
                                 std::ostream& err);

} // namespace apcs
