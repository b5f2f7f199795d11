#include "apcs/animation/surface_fit.h"

#include "apcs/base/parallel_work.h"

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

std::vector<double> chord_places(std::span<const Vec3> points, Closure closure)
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

std::vector<double> graphic_parameters(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure)
{
    const std::vector<double> first = chord_places(key1, closure);
    const std::vector<double> second = chord_places(key2, closure);
    std::vector<double> parameters(std::min(first.size(), second.size()));
    for (std::size_t i = 0; i < parameters.size(); ++i)
        parameters[i] = (first[i] + second[i]) / 2.0;
    return parameters;
}

SurfaceFitter::SurfaceFitter(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure,
                             EdgePath first_edge, EdgePath last_edge)
    : m_closed(closure == Closure::closed)
    , m_point_count(std::min(key1.size(), key2.size()))
{
    m_key1 = key1.first(m_point_count);
    m_key2 = key2.first(m_point_count);
    // A closed graphic's last point is its first (SPEC §5.3): both edges are the first path.
    m_second_edge = m_closed ? first_edge : std::move(last_edge);
    m_first_edge = std::move(first_edge);
    m_frame_count = std::min(m_first_edge.positions.size(), m_second_edge.positions.size());
    if (m_point_count == 0)
        return;
    // The blend across the graphic, F1(v_i) and F2(v_i), per point.
    const std::vector<double> v = graphic_parameters(m_key1, m_key2, closure);
    m_across.reserve(m_point_count);
    for (const double place : v) {
        const HermiteBasis weights = hermite_basis(place);
        m_across.emplace_back(weights.f1, weights.f2);
    }
    m_last_follows_edge = !m_closed || (m_key1.back() == m_key1.front() && m_key2.back() == m_key2.front());
}

SurfaceFitter::SurfaceFitter(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure,
                             EdgePath first_edge, EdgePath last_edge, const FergusonCorners& corners)
    : SurfaceFitter(key1, key2, closure, std::move(first_edge), std::move(last_edge))
{
    const std::vector<HermiteSegment> paths = ferguson_point_paths(m_key1, m_key2, closure, corners);
    // Measuring a path costs about as much as placing its point in five frames: both cores share it.
    m_ferguson_paths.resize(paths.size());
    constexpr std::size_t paths_worth_a_thread = 2048;
    split_across_cores(paths.size(), paths_worth_a_thread, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i)
            m_ferguson_paths[i] = MeasuredSegment(paths[i]);
    });
}

void SurfaceFitter::fit(std::size_t k, std::size_t first, std::span<Vec3> out) const
{
    if (k == 0 || k + 1 == m_frame_count) {
        // The key frames themselves, exactly, not as rounded blends.
        const std::span<const Vec3> key = k == 0 ? m_key1 : m_key2;
        std::copy_n(key.begin() + static_cast<std::ptrdiff_t>(first), out.size(), out.begin());
        return;
    }
    const Vec3 key1_first = m_key1.front();
    const Vec3 key2_first = m_key2.front();
    const Vec3 key1_last = m_closed ? key1_first : m_key1.back();
    const Vec3 key2_last = m_closed ? key2_first : m_key2.back();
    const Vec3 edge0 = m_first_edge.positions[k];
    const Vec3 edge1 = m_second_edge.positions[k];
    const double progress0 = m_first_edge.progress[k];
    const double progress1 = m_second_edge.progress[k];
    // How far each edge path bends off its chord at this frame.
    const Vec3 bend0 = edge0 - lerp(key1_first, key2_first, progress0);
    const Vec3 bend1 = edge1 - lerp(key1_last, key2_last, progress1);
    for (std::size_t j = 0; j < out.size(); ++j) {
        const std::size_t i = first + j;
        const auto [f1, f2] = m_across[i];
        const double progress = f1 * progress0 + f2 * progress1;
        // SPEC §5.3.1: the thesis' surface places the point on its own Ferguson path instead.
        out[j] = m_ferguson_paths.empty() ? lerp(m_key1[i], m_key2[i], progress) + f1 * bend0 + f2 * bend1
                                          : m_ferguson_paths[i].at_arc_fraction(progress);
    }
    // The edge points follow their paths exactly (for v = 0 and v = 1 the blend already does, up
    // to rounding).
    if (first == 0 && !out.empty())
        out[0] = edge0;
    if (m_last_follows_edge && first + out.size() == m_point_count && !out.empty())
        out.back() = edge1;
}

namespace {

FrameSequence all_frames(const SurfaceFitter& fitter)
{
    FrameSequence frames(fitter.frame_count(), fitter.point_count());
    // Each frame's points on both cores: a Ferguson point costs an arc-length search.
    constexpr std::size_t points_worth_a_thread = 4096;
    for (std::size_t k = 0; k < frames.frame_count(); ++k) {
        const std::span<Vec3> frame = frames.frame(k);
        split_across_cores(frame.size(), points_worth_a_thread, [&](std::size_t first, std::size_t end) {
            fitter.fit(k, first, frame.subspan(first, end - first));
        });
    }
    return frames;
}

} // namespace

FrameSequence fit_surface(std::span<const Vec3> key1, std::span<const Vec3> key2, Closure closure,
                          const EdgePath& first_edge, const EdgePath& last_edge)
{
    return all_frames(SurfaceFitter(key1, key2, closure, first_edge, last_edge));
}

std::span<const Vec3> contiguous_points(const Graphic& graphic, std::vector<Vec3>& storage)
{
    if (graphic.parts.size() == 1)
        return graphic.parts.front().points;
    storage = graphic.all_points();
    return storage;
}

SurfaceFitter key_frames_fitter(const EqualisedKeys& keys, const EvaluatedPath& first_path,
                                const EvaluatedPath& last_path, std::array<std::vector<Vec3>, 2>& storage,
                                SurfaceConstruction construction)
{
    const std::span<const Vec3> key1 = contiguous_points(keys.key1, storage[0]);
    const std::span<const Vec3> key2 = contiguous_points(keys.key2, storage[1]);
    const Closure closure = keys.key1.is_closed() ? Closure::closed : Closure::open;
    if (key1.empty() || key2.empty())
        return SurfaceFitter(key1, key2, closure, {}, {});
    EdgePath first_edge = edge_path_from(first_path, key1.front(), key2.front());
    EdgePath last_edge = edge_path_from(last_path, key1.back(), key2.back());
    if (construction == SurfaceConstruction::blend)
        return SurfaceFitter(key1, key2, closure, std::move(first_edge), std::move(last_edge));
    const FergusonCorners corners{edge_tangents_of(first_path), edge_tangents_of(last_path)};
    return SurfaceFitter(key1, key2, closure, std::move(first_edge), std::move(last_edge), corners);
}

FrameSequence fit_key_frames(const EqualisedKeys& keys, const EvaluatedPath& first_path, const EvaluatedPath& last_path,
                             SurfaceConstruction construction)
{
    std::array<std::vector<Vec3>, 2> storage;
    return all_frames(key_frames_fitter(keys, first_path, last_path, storage, construction));
}

} // namespace apcs
