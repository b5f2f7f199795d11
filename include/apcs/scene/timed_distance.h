#pragma once

#include <span>
#include <vector>

namespace apcs {

// The slides' distance–time function S(t) (seed 004, "(0,A), (10,B), (35,C), (60,D)") for a MOVE
// with TIMES: through the points (F_k, s_k), s_k the arc length at control point k, monotone
// (never runs back while the s_k do not decrease) and with a continuous slope at every F_k, so the
// speed does not jump at a key. It is the monotone cubic Hermite interpolant of Fritsch and
// Carlson: interior slopes the weighted harmonic mean of the neighbouring spans' average speeds
// (Brodlie's weights), 0 where a span does not move; end slopes by the three-point formula,
// limited to keep the ends monotone. One span runs at even speed.
class TimedDistance {
public:
    // `frames` strictly increasing, `distances` non-decreasing, as many of each (at least one).
    TimedDistance(std::span<const int> frames, std::span<const double> distances);
    // S(f): distances.front() before the first frame, distances.back() after the last.
    double at(double frame) const;
    double slope_at_key(std::size_t key) const { return m_slopes[key]; }

private:
    std::vector<double> m_frames;
    std::vector<double> m_distances;
    std::vector<double> m_slopes;
};

} // namespace apcs
