#include "apcs/animation/vector_inbetween.h"

#include "apcs/animation/add_points.h"

#include <algorithm>
#include <array>
#include <utility>

namespace apcs {

namespace {

constexpr std::array<std::pair<Padding, std::string_view>, 5> padding_names{{
    {Padding::apcs, "apcs"},
    {Padding::start, "start"},
    {Padding::end, "end"},
    {Padding::middle, "middle"},
    {Padding::midpoint, "midpoint"},
}};

// s_i = ⌈i·m/(n−m)⌉ for i = 1 … n−m, as 1-based indices into the m points: how many times each
// point is chosen.
std::vector<std::size_t> chosen_counts(std::size_t m, std::size_t added)
{
    std::vector<std::size_t> counts(m + 1, 0);
    for (std::size_t i = 1; i <= added; ++i) {
        const std::size_t s = (i * m + added - 1) / added;
        ++counts[std::clamp<std::size_t>(s, 1, m)];
    }
    return counts;
}

} // namespace

std::optional<Padding> padding_from_name(std::string_view name)
{
    for (const auto& [padding, padding_name] : padding_names)
        if (padding_name == name)
            return padding;
    return std::nullopt;
}

std::vector<Vec3> pad_points(std::span<const Vec3> points, std::size_t target_count, Padding padding)
{
    std::vector<Vec3> padded(points.begin(), points.end());
    if (points.empty() || points.size() >= target_count)
        return padded;
    const std::size_t m = points.size();
    const std::size_t added = target_count - m;
    switch (padding) {
    case Padding::apcs:
        return add_points(points, target_count);
    case Padding::start:
        padded.insert(padded.begin(), added, points.front());
        return padded;
    case Padding::end:
        padded.insert(padded.end(), added, points.back());
        return padded;
    case Padding::middle:
    case Padding::midpoint: {
        const std::vector<std::size_t> counts = chosen_counts(m, added);
        padded.clear();
        padded.reserve(target_count);
        for (std::size_t s = 1; s <= m; ++s) {
            const Vec3& point = points[s - 1];
            padded.push_back(point);
            const Vec3 inserted =
                padding == Padding::middle || s == m ? point : lerp(point, points[s], 0.5);
            padded.insert(padded.end(), counts[s], inserted);
        }
        return padded;
    }
    }
    return padded;
}

FrameSequence interpolate_frames(std::span<const Vec3> begin, std::span<const Vec3> end, int intervals, SpeedLaw law)
{
    const std::size_t point_count = std::min(begin.size(), end.size());
    const int frame_intervals = std::max(intervals, 1);
    FrameSequence frames(static_cast<std::size_t>(frame_intervals) + 1, point_count);
    for (int i = 0; i <= frame_intervals; ++i) {
        std::span<Vec3> frame = frames.frame(static_cast<std::size_t>(i));
        if (i == 0 || i == frame_intervals) {
            std::copy_n((i == 0 ? begin : end).begin(), point_count, frame.begin());
            continue;
        }
        const double f = distance_fraction(law, static_cast<double>(i) / frame_intervals);
        for (std::size_t p = 0; p < point_count; ++p)
            frame[p] = begin[p] + f * (end[p] - begin[p]);
    }
    return frames;
}

} // namespace apcs
