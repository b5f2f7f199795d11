#pragma once

#include "apcs/geometry/vec3.h"

#include <algorithm>
#include <span>

namespace apcs {

// Axis-aligned box around a set of world points; empty until a point is added.
class BoundingBox {
public:
    void add(const Vec3& point)
    {
        if (m_empty) {
            m_low = m_high = point;
            m_empty = false;
            return;
        }
        m_low = {std::min(m_low.x, point.x), std::min(m_low.y, point.y), std::min(m_low.z, point.z)};
        m_high = {std::max(m_high.x, point.x), std::max(m_high.y, point.y), std::max(m_high.z, point.z)};
    }
    void add(std::span<const Vec3> points)
    {
        for (const Vec3& point : points)
            add(point);
    }
    // The box around both boxes' points: as adding `other`'s points one by one after this one's
    // (the extremes of points that are not NaN do not depend on their order; a tie keeps this one's).
    void join(const BoundingBox& other)
    {
        if (other.m_empty)
            return;
        if (m_empty) {
            *this = other;
            return;
        }
        m_low = {std::min(m_low.x, other.m_low.x), std::min(m_low.y, other.m_low.y), std::min(m_low.z, other.m_low.z)};
        m_high = {std::max(m_high.x, other.m_high.x), std::max(m_high.y, other.m_high.y),
                  std::max(m_high.z, other.m_high.z)};
    }
    bool empty() const { return m_empty; }
    Vec3 low() const { return m_low; }
    Vec3 high() const { return m_high; }
    Vec3 centre() const { return (m_low + m_high) * 0.5; }
    double half_diagonal() const { return length(m_high - m_low) * 0.5; }

private:
    Vec3 m_low;
    Vec3 m_high;
    bool m_empty = true;
};

} // namespace apcs
