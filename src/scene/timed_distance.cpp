#include "apcs/scene/timed_distance.h"

#include <algorithm>
#include <cmath>

namespace apcs {

namespace {

// The end slope of PCHIP from the first two spans (h0, d0) and (h1, d1).
double end_slope(double h0, double h1, double d0, double d1)
{
    const double slope = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    if (slope * d0 <= 0.0)
        return 0.0;
    if (d0 * d1 < 0.0 && std::abs(slope) > 3.0 * std::abs(d0))
        return 3.0 * d0;
    return slope;
}

} // namespace

TimedDistance::TimedDistance(std::span<const int> frames, std::span<const double> distances)
    : m_frames(frames.begin(), frames.end())
    , m_distances(distances.begin(), distances.end())
    , m_slopes(frames.size(), 0.0)
{
    const std::size_t spans = m_frames.size() - 1;
    if (spans == 0)
        return;
    std::vector<double> width(spans);
    std::vector<double> speed(spans);
    for (std::size_t k = 0; k < spans; ++k) {
        width[k] = m_frames[k + 1] - m_frames[k];
        speed[k] = (m_distances[k + 1] - m_distances[k]) / width[k];
    }
    if (spans == 1) {
        m_slopes = {speed[0], speed[0]};
        return;
    }
    for (std::size_t k = 1; k < spans; ++k) {
        if (speed[k - 1] * speed[k] <= 0.0)
            continue;
        const double w1 = 2.0 * width[k] + width[k - 1];
        const double w2 = width[k] + 2.0 * width[k - 1];
        m_slopes[k] = (w1 + w2) / (w1 / speed[k - 1] + w2 / speed[k]);
    }
    m_slopes.front() = end_slope(width[0], width[1], speed[0], speed[1]);
    m_slopes.back() = end_slope(width[spans - 1], width[spans - 2], speed[spans - 1], speed[spans - 2]);
}

double TimedDistance::at(double frame) const
{
    if (frame <= m_frames.front())
        return m_distances.front();
    if (frame >= m_frames.back())
        return m_distances.back();
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(m_frames.begin(), m_frames.end(), frame) - m_frames.begin()) - 1;
    const double h = m_frames[k + 1] - m_frames[k];
    const double t = (frame - m_frames[k]) / h;
    const double t2 = t * t;
    const double t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * m_distances[k] + (t3 - 2 * t2 + t) * h * m_slopes[k] +
           (-2 * t3 + 3 * t2) * m_distances[k + 1] + (t3 - t2) * h * m_slopes[k + 1];
}

} // namespace apcs
