#pragma once

#include "apcs/geometry/vec3.h"

#include <span>
#include <vector>

namespace apcs {

// Frames of one graphic, every frame with the same point count, stored frame after frame in one
// contiguous array (no allocation per point or per frame). Frames of no points still count (a
// scene of groups only has frames to play, each empty).
class FrameSequence {
public:
    FrameSequence() = default;
    FrameSequence(std::size_t frame_count, std::size_t points_per_frame)
        : m_frame_count(frame_count)
        , m_points_per_frame(points_per_frame)
        , m_points(frame_count * points_per_frame)
    {
    }

    std::size_t frame_count() const { return m_frame_count; }
    std::size_t points_per_frame() const { return m_points_per_frame; }
    std::span<const Vec3> frame(std::size_t index) const
    {
        return std::span(m_points).subspan(index * m_points_per_frame, m_points_per_frame);
    }
    std::span<Vec3> frame(std::size_t index)
    {
        return std::span(m_points).subspan(index * m_points_per_frame, m_points_per_frame);
    }

private:
    std::size_t m_frame_count = 0;
    std::size_t m_points_per_frame = 0;
    std::vector<Vec3> m_points;
};

} // namespace apcs
