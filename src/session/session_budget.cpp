#include "session_budget.h"

#include "apcs/animation/memory_budget.h"

namespace apcs {

Expected<void> check_frames_fit(std::size_t key_points, const SessionSettings& settings)
{
    const memory::FramesRequest request{static_cast<std::size_t>(std::max(settings.inbetween_count, 0)) + 2, key_points,
                                        false};
    return memory::check_fits(
        memory::describe(request) + " (--inbetweens " + std::to_string(settings.inbetween_count) + ")",
        memory::frames_bytes(request), settings.memory_limit_bytes,
        "use key frames of fewer points, or start apcs with a lower --inbetweens");
}

Expected<void> check_path_fits(std::size_t control_points, const SessionSettings& settings)
{
    const memory::PathRequest request{control_points, settings.samples_per_segment, settings.inbetween_count, false};
    return memory::check_fits(memory::describe(request), memory::path_bytes(request), settings.memory_limit_bytes,
                              "use a path of fewer control points, or start apcs with a lower --samples or --inbetweens");
}

} // namespace apcs
