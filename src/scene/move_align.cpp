#include "move_align.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace apcs {

namespace {

Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

Vec3 unit(const Vec3& v) { return v * (1.0 / length(v)); }

// The path as a polyline: its KB curve sampled at least 256 times a segment, so that a chord of
// it is within a thousandth of a radian of the tangent on curves as tight as a wheel's road.
std::vector<Vec3> path_polyline(const SceneMove& move, const PathSettings& settings)
{
    PathSettings dense = settings;
    dense.samples_per_segment = std::max(settings.samples_per_segment, 256);
    dense.inbetween_count = 0;
    return evaluate_path(move.path, dense).curve.samples();
}

// The polyline segment (i, i + 1) nearest `point`, and where on it (t in [0, 1]).
struct PlaceOnPolyline {
    std::size_t segment = 0;
    double t = 0.0;
};

PlaceOnPolyline nearest_place(std::span<const Vec3> line, const Vec3& point)
{
    PlaceOnPolyline best;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec3 along = line[i + 1] - line[i];
        const double span = dot(along, along);
        const double t = span > 0.0 ? std::clamp(dot(point - line[i], along) / span, 0.0, 1.0) : 0.0;
        const double d = distance(line[i] + along * t, point);
        if (d < best_distance) {
            best_distance = d;
            best = {i, t};
        }
    }
    return best;
}

// The first point of the polyline after `place` that is `ahead` from `point` in a straight line.
std::optional<Vec3> point_ahead(std::span<const Vec3> line, PlaceOnPolyline place, const Vec3& point, double ahead)
{
    for (std::size_t i = place.segment; i + 1 < line.size(); ++i) {
        const Vec3 a = i == place.segment ? line[i] + (line[i + 1] - line[i]) * place.t : line[i];
        const Vec3 b = line[i + 1];
        if (distance(point, b) < ahead)
            continue;
        // |a + s(b − a) − point| = ahead on s in [0, 1]: the larger root, a being nearer than b.
        const Vec3 along = b - a;
        const Vec3 from = a - point;
        const double qa = dot(along, along);
        const double qb = 2.0 * dot(from, along);
        const double qc = dot(from, from) - ahead * ahead;
        const double s = qa > 0.0 ? (-qb + std::sqrt(std::max(0.0, qb * qb - 4.0 * qa * qc))) / (2.0 * qa) : 0.0;
        return a + along * std::clamp(s, 0.0, 1.0);
    }
    return std::nullopt;
}

// The path's direction at `point`: its tangent there, or the chord to the point `ahead` away.
std::optional<Vec3> direction_at(std::span<const Vec3> line, const Vec3& point, std::optional<double> ahead)
{
    const PlaceOnPolyline place = nearest_place(line, point);
    if (ahead) {
        const std::optional<Vec3> front = point_ahead(line, place, point, *ahead);
        // A chord lost in round-off has no direction: the last one is kept (SPEC §8.1), never NaN.
        if (!front || !(length(*front - point) > 0.0))
            return std::nullopt;
        return *front - point;
    }
    const Vec3 along = line[place.segment + 1] - line[place.segment];
    if (!(length(along) > 0.0))
        return std::nullopt;
    return along;
}

} // namespace

Affine smallest_rotation(const Vec3& from, const Vec3& to)
{
    const Vec3 a = unit(from);
    const Vec3 b = unit(to);
    const Vec3 v = cross(a, b);
    const double c = dot(a, b);
    Affine turn;
    if (c < -1.0 + 1e-12) {
        // Half a turn about an axis across `a`: R = 2·n·nᵀ − I.
        const Vec3 n = unit(std::abs(a.x) < 0.9 ? cross(a, Vec3{1, 0, 0}) : cross(a, Vec3{0, 1, 0}));
        const double axis[3] = {n.x, n.y, n.z};
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j)
                turn.m[i][j] = 2.0 * axis[i] * axis[j] - (i == j ? 1.0 : 0.0);
        return turn;
    }
    // Rodrigues: R = I + [v]× + [v]×² / (1 + c).
    const double k[3][3] = {{0, -v.z, v.y}, {v.z, 0, -v.x}, {-v.y, v.x, 0}};
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = 0; j < 3; ++j) {
            double square = 0.0;
            for (std::size_t l = 0; l < 3; ++l)
                square += k[i][l] * k[l][j];
            turn.m[i][j] = (i == j ? 1.0 : 0.0) + k[i][j] + square / (1.0 + c);
        }
    return turn;
}

std::vector<Affine> align_turns(const SceneMove& move, std::span<const Vec3> offsets, const PathSettings& settings)
{
    const std::vector<Vec3> line = path_polyline(move, settings);
    const Vec3 start = move.path.front().position;
    std::vector<Affine> turns;
    turns.reserve(offsets.size());
    const std::optional<Vec3> first = line.size() < 2 ? std::nullopt : direction_at(line, start, move.ahead);
    Vec3 last = first.value_or(Vec3{0, 1, 0});
    for (const Vec3& offset : offsets) {
        if (const std::optional<Vec3> now = direction_at(line, start + offset, move.ahead); now && length(*now) > 0.0)
            last = *now;
        const Affine rotation = first ? smallest_rotation(*first, last) : Affine{};
        // About P_0: the rider stays where the path carries it.
        Affine about = rotation;
        about.t = start - rotation(start);
        turns.push_back(about);
    }
    return turns;
}

} // namespace apcs
