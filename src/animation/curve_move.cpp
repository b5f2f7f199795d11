#include "apcs/animation/curve_move.h"

#include <algorithm>
#include <vector>

namespace apcs {

namespace {

// The point of the line piece from `start` to `end` nearest to `point`.
Vec3 nearest_on_piece(const Vec3& point, const Vec3& start, const Vec3& end)
{
    const Vec3 along = end - start;
    const double squared = dot(along, along);
    if (squared <= 0.0)
        return start;
    return start + along * std::clamp(dot(point - start, along) / squared, 0.0, 1.0);
}

} // namespace

SampleMove furthest_sample_move(const HermiteSegment& before, const HermiteSegment& after,
                                std::span<const HermiteBasis> basis, double at_least, int window)
{
    // A cheap bound first: most segments of a long path's global key stop here.
    double same_sample = 0.0;
    for (const HermiteBasis& weights : basis)
        same_sample = std::max(same_sample, length(after.apply(weights) - before.apply(weights)));
    SampleMove furthest{before.start, after.start, 0.0};
    if (same_sample <= at_least || basis.size() < 2)
        return furthest;
    std::vector<Vec3> was;
    std::vector<Vec3> is;
    for (const HermiteBasis& weights : basis) {
        was.push_back(before.apply(weights));
        is.push_back(after.apply(weights));
    }
    const auto reach = static_cast<std::size_t>(std::max(window, 1));
    for (std::size_t j = 0; j < is.size(); ++j) {
        SampleMove nearest{was[j], is[j], length(is[j] - was[j])};
        const std::size_t from = j > reach ? j - reach : 0;
        const std::size_t to = std::min(j + reach, was.size() - 1);
        for (std::size_t piece = from; piece < to; ++piece) {
            const Vec3 on = nearest_on_piece(is[j], was[piece], was[piece + 1]);
            if (const double distance = length(is[j] - on); distance < nearest.distance)
                nearest = {on, is[j], distance};
        }
        if (nearest.distance > furthest.distance)
            furthest = nearest;
    }
    return furthest;
}

} // namespace apcs
