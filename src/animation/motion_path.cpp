#include "apcs/animation/motion_path.h"

#include "apcs/animation/arc_length.h"
#include "apcs/animation/input_limits.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/speed_law.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace apcs {

std::vector<AccelerationSpan> acceleration_spans(std::span<const ControlPoint> points)
{
    std::vector<AccelerationSpan> spans;
    if (points.size() < 2)
        return spans;
    const std::size_t last = points.size() - 1;
    const auto acceleration = [&](std::size_t k) { return limits::staff_value.clamp(points[k].staff.acceleration); };
    AccelerationSpan current{0, last, acceleration(0)};
    for (std::size_t k = 1; k < last; ++k) {
        if (acceleration(k) != current.acceleration) {
            current.last_point = k;
            spans.push_back(current);
            current = {k, last, acceleration(k)};
        }
    }
    spans.push_back(current);
    return spans;
}

std::vector<int> share_by_largest_remainder(std::span<const double> weights, int total)
{
    std::vector<int> shares(weights.size(), 0);
    if (weights.empty() || total <= 0)
        return shares;
    double weight_sum = std::accumulate(weights.begin(), weights.end(), 0.0);
    std::vector<double> quotas(weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i)
        quotas[i] = weight_sum > 0.0 ? total * std::max(weights[i], 0.0) / weight_sum
                                     : static_cast<double>(total) / static_cast<double>(weights.size());
    int given = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        shares[i] = static_cast<int>(std::floor(quotas[i]));
        given += shares[i];
    }
    std::vector<std::size_t> order(weights.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t left, std::size_t right) {
        return quotas[left] - shares[left] > quotas[right] - shares[right];
    });
    for (std::size_t i = 0; given < total; i = (i + 1) % order.size(), ++given)
        ++shares[order[i]];
    return shares;
}

namespace {

// Target distances of one span's in-betweens, measured from the span's start (SPEC §4.3).
std::vector<double> span_targets(double span_start, double span_length, int count, double acceleration)
{
    std::vector<double> targets;
    targets.reserve(static_cast<std::size_t>(count));
    for (int j = 1; j <= count; ++j) {
        const double tau = static_cast<double>(j) / (count + 1);
        targets.push_back(span_start + span_length * acceleration_distance_fraction(tau, acceleration));
    }
    return targets;
}

} // namespace

EvaluatedPath evaluate_path(std::span<const ControlPoint> points, const PathSettings& settings)
{
    EvaluatedPath path;
    evaluate_path(points, settings, path);
    return path;
}

void evaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path)
{
    kb_segments(points, settings.slopes, path.curve.segments);
    sample_curve(path.curve, settings.samples_per_segment);
    place_inbetweens(points, settings, path);
}

void place_inbetweens(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path)
{
    path.inbetweens.clear();
    path.span_timings.clear();
    path.frames_freeze = false;
    if (path.curve.segments.empty())
        return;
    const int inbetween_count = std::max(settings.inbetween_count, 0);

    const std::vector<AccelerationSpan> spans = acceleration_spans(points);
    const bool exact = settings.spacing == Spacing::exact;
    const ArcLengthTable arc_table = exact ? ArcLengthTable(path.curve.segments) : ArcLengthTable({});
    // Distance from the curve's start to control point k, in the measure the spacing uses.
    const auto boundary = [&](std::size_t control_point) {
        return exact ? arc_table.length_to_segment_start(control_point)
                     : path.curve.length_to_point[control_point];
    };
    const double total = exact ? arc_table.total_length() : path.curve.total_length();

    path.inbetweens.reserve(static_cast<std::size_t>(inbetween_count));
    if (!(total > 0.0)) {
        // A path of zero length (a point that stays) still has a pace: its in-betweens progress by
        // the first control point's law over one span, so that surface fitting never sees a
        // neighbour stand still and then jump (SPEC §5.3).
        for (int j = 1; j <= inbetween_count; ++j) {
            const double tau = static_cast<double>(j) / (inbetween_count + 1);
            path.inbetweens.push_back(
                {path.curve.segments.front().start, acceleration_distance_fraction(tau, points.front().staff.acceleration), 0});
        }
        return;
    }

    std::vector<double> span_lengths;
    for (const AccelerationSpan& span : spans)
        span_lengths.push_back(boundary(span.last_point) - boundary(span.first_point));
    const std::vector<int> shares = share_by_largest_remainder(span_lengths, inbetween_count);

    for (std::size_t s = 0; s < spans.size(); ++s) {
        const double start = boundary(spans[s].first_point);
        path.span_timings.push_back({spans[s], start / total, span_lengths[s] / total, path.inbetweens.size(),
                                     static_cast<std::size_t>(shares[s])});
        for (const double target : span_targets(start, span_lengths[s], shares[s], spans[s].acceleration)) {
            Inbetween shown;
            if (exact) {
                shown.position = arc_table.point_at(arc_table.parameter_at(target));
                shown.arc_fraction = target / total;
                const double chord_target = shown.arc_fraction * path.curve.total_length();
                shown.sample_index = path.curve.nearest_sample(chord_target);
            } else {
                shown.sample_index = path.curve.nearest_sample(target);
                shown.position = path.curve.sample(shown.sample_index);
                shown.arc_fraction = path.curve.chord_length(shown.sample_index) / total;
            }
            path.inbetweens.push_back(shown);
        }
    }
    // With the thesis' nearest samples two in-betweens can fall on one sample: that frame repeats.
    if (!exact)
        for (std::size_t j = 1; j < path.inbetweens.size(); ++j)
            path.frames_freeze = path.frames_freeze || path.inbetweens[j].sample_index == path.inbetweens[j - 1].sample_index;
}

void reevaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                     std::size_t first_changed, std::size_t last_changed)
{
    const bool same_shape_of_arrays = points.size() >= 2 && path.curve.segments.size() == points.size() - 1 &&
                                      path.curve.samples_per_segment == std::max(settings.samples_per_segment, 1) &&
                                      path.curve.segment_length.size() == path.curve.segments.size();
    if (!same_shape_of_arrays || first_changed > last_changed) {
        evaluate_path(points, settings, path);
        return;
    }
    // Control point k's tangents shape segments k − 1 and k.
    const std::size_t first = first_changed == 0 ? 0 : first_changed - 1;
    const std::size_t end = std::min(last_changed + 1, path.curve.segments.size());
    std::size_t changed_first = end;
    std::size_t changed_end = first;
    for (std::size_t s = first; s < end; ++s) {
        const HermiteSegment segment = kb_segment(points, settings.slopes, s);
        if (segment == path.curve.segments[s])
            continue;
        path.curve.segments[s] = segment;
        changed_first = std::min(changed_first, s);
        changed_end = s + 1;
    }
    if (changed_first < changed_end)
        remeasure_segments(path.curve, changed_first, changed_end);
    place_inbetweens(points, settings, path);
}


} // namespace apcs
