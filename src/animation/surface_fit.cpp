#include "apcs/animation/surface_fit.h"

#include "apcs/animation/hermite.h"

#include <algorithm>

namespace apcs {

EdgePath edge_path_from(const EvaluatedPath& path, const Vec3& key1_position, const Vec3& key2_position)
{
    EdgePath edge;
    edge.positions.reserve(path.inbetweens.size() + 2);
    edge.progress.reserve(path.inbetweens.size() + 2);
    edge.positions.push_back(key1_position);
    edge.progress.push_back(0.0);
    for (const Inbetween& inbetween : path.inbetweens) {
        edge.positions.push_back(inbetween.position);
        edge.progress.push_back(inbetween.arc_fraction);
    }
    edge.positions.push_back(key2_position);
    edge.progress.push_back(1.0);
    return edge;
}

namespace {

std::vector<double> chord_fractions(std::span<const Vec3> points, Closure closure)
{
    std::vector<double> fractions(points.size(), 0.0);
    if (points.size() < 2)
        return fractions;
    for (std::size_t i = 1; i < points.size(); ++i)
        fractions[i] = fractions[i - 1] + distance(points[i - 1], points[i]);
    double total = fractions.back();
    if (closure == Closure::closed)
        total += distance(points.back(), points.front());
    for (std::size_t i = 0; i < points.size(); ++i)
        fractions[i] = total > 0.0 ? fractions[i] / total : static_cast<double>(i) / static_cast<double>(points.size() - 1);
    return fractions;
}

} // namespace

std::vector<double> graphic_parameters(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure)
{
    const std::vector<double> first = chord_fractions(key1, closure);
    const std::vector<double> second = chord_fractions(key2, closure);
    std::vector<double> parameters(std::min(first.size(), second.size()));
    for (std::size_t i = 0; i < parameters.size(); ++i)
        parameters[i] = (first[i] + second[i]) / 2.0;
    return parameters;
}

FrameSequence fit_surface(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure,
                          const EdgePath& first_edge, const EdgePath& last_edge)
{
    const std::size_t point_count = std::min(key1.size(), key2.size());
    const bool closed = closure == Closure::closed;
    const EdgePath& second_edge = closed ? first_edge : last_edge;
    const std::size_t frame_count = std::min(first_edge.positions.size(), second_edge.positions.size());
    FrameSequence frames(frame_count, point_count);
    if (point_count == 0 || frame_count == 0)
        return frames;

    // The blend across the graphic, F1(v_i) and F2(v_i), per point.
    const std::vector<double> v = graphic_parameters(key1.first(point_count), key2.first(point_count), closure);
    std::vector<HermiteBasis> across(point_count);
    for (std::size_t i = 0; i < point_count; ++i)
        across[i] = hermite_basis(v[i]);
    // A closed graphic's last point is its first (SPEC §5.3): both edges are the first path.
    const Vec3 key1_first = key1.front();
    const Vec3 key2_first = key2.front();
    const Vec3 key1_last = closed ? key1_first : key1[point_count - 1];
    const Vec3 key2_last = closed ? key2_first : key2[point_count - 1];

    const std::size_t last_frame = frame_count - 1;
    for (std::size_t k = 0; k < frame_count; ++k) {
        std::span<Vec3> frame = frames.frame(k);
        if (k == 0 || k == last_frame) {
            // The key frames themselves, exactly, not as rounded blends.
            const std::span<const Vec3> key = k == 0 ? key1 : key2;
            std::copy_n(key.begin(), point_count, frame.begin());
            continue;
        }
        const Vec3 edge0 = first_edge.positions[k];
        const Vec3 edge1 = second_edge.positions[k];
        const double progress0 = first_edge.progress[k];
        const double progress1 = second_edge.progress[k];
        // How far each edge path bends off its chord at this frame.
        const Vec3 bend0 = edge0 - lerp(key1_first, key2_first, progress0);
        const Vec3 bend1 = edge1 - lerp(key1_last, key2_last, progress1);
        for (std::size_t i = 0; i < point_count; ++i) {
            const HermiteBasis& weights = across[i];
            const double progress = weights.f1 * progress0 + weights.f2 * progress1;
            frame[i] = lerp(key1[i], key2[i], progress) + weights.f1 * bend0 + weights.f2 * bend1;
        }
        // The edge points follow their paths exactly (for v = 0 and v = 1 the blend already does,
        // up to rounding).
        frame[0] = edge0;
        if (!closed || (key1[point_count - 1] == key1_first && key2[point_count - 1] == key2_first))
            frame[point_count - 1] = edge1;
    }
    return frames;
}

FrameSequence fit_key_frames(const EqualisedKeys& keys, const EvaluatedPath& first_path, const EvaluatedPath& last_path)
{
    const std::vector<Vec3> key1 = keys.key1.all_points();
    const std::vector<Vec3> key2 = keys.key2.all_points();
    if (key1.empty() || key2.empty())
        return {};
    const Closure closure = keys.key1.is_closed() ? Closure::closed : Closure::open;
    const EdgePath first_edge = edge_path_from(first_path, key1.front(), key2.front());
    const EdgePath last_edge = edge_path_from(last_path, key1.back(), key2.back());
    return fit_surface(key1, key2, closure, first_edge, last_edge);
}

} // namespace apcs
