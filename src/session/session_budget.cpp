#include "apcs/session/session_budget.h"

#include "apcs/animation/memory_budget.h"

namespace apcs {

namespace {

// The refusal's message is the step's (session_budget.h keeps optional<string> until the session
// takes Expected).
std::optional<std::string> message_of(const Expected<void>& fits)
{
    if (fits)
        return std::nullopt;
    return fits.error().message;
}

} // namespace

std::optional<std::string> frames_refusal(std::size_t key_points, const SessionSettings& settings)
{
    const memory::FramesRequest request{static_cast<std::size_t>(std::max(settings.inbetween_count, 0)) + 2, key_points,
                                        false};
    return message_of(memory::check_fits(
        memory::describe(request) + " (--inbetweens " + std::to_string(settings.inbetween_count) + ")",
        memory::frames_bytes(request), settings.memory_limit_bytes,
        "use key frames of fewer points, or start apcs with a lower --inbetweens"));
}

std::optional<std::string> path_refusal(std::size_t control_points, const SessionSettings& settings)
{
    const memory::PathRequest request{control_points, settings.samples_per_segment, settings.inbetween_count, false};
    return message_of(
        memory::check_fits(memory::describe(request), memory::path_bytes(request), settings.memory_limit_bytes,
                           "use a path of fewer control points, or start apcs with a lower --samples or --inbetweens"));
}

} // namespace apcs
