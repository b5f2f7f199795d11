#include "apcs/animation/motion_path.h"

#include "apcs/animation/arc_length.h"
#include "apcs/animation/input_limits.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/speed_law.h"
#include "apcs/base/parallel_work.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace apcs {

// A span ends where a point's acceleration differs from the one before it: the points are
// searched for those places in two halves on two cores (a key on 10^6 control points does this).
std::vector<AccelerationSpan> acceleration_spans(std::span<const ControlPoint> points)
{
    std::vector<AccelerationSpan> spans;
    if (points.size() < 2)
        return spans;
    const std::size_t last = points.size() - 1;
    const auto acceleration = [&](std::size_t k) { return limits::staff_value.clamp(points[k].staff.acceleration); };
    std::array<std::vector<std::size_t>, 2> halves;
    split_across_cores(last - 1, 1 << 16, [&](std::size_t from, std::size_t to) {
        std::vector<std::size_t> starts;
        for (std::size_t k = from + 1; k < to + 1; ++k)
            if (acceleration(k) != acceleration(k - 1))
                starts.push_back(k);
        halves[from == 0 ? 0 : 1] = std::move(starts);
    });
    std::size_t first = 0;
    for (const std::vector<std::size_t>& starts : halves)
        for (const std::size_t start : starts) {
            spans.push_back({first, start, acceleration(first)});
            first = start;
        }
    spans.push_back({first, last, acceleration(first)});
    return spans;
}

std::vector<AccelerationSpan> acceleration_spans_after(std::span<const AccelerationSpan> before,
                                                      std::span<const ControlPoint> points, const PathChange& change)
{
    std::vector<AccelerationSpan> spans;
    if (points.size() < 2)
        return spans;
    const std::size_t last = points.size() - 1;
    const auto acceleration = [&](std::size_t k) { return limits::staff_value.clamp(points[k].staff.acceleration); };
    const std::size_t changed_end = change.first + change.inserted; // new numbering, the point after
    const std::size_t old_count = points.size() - change.inserted + change.removed;
    // A span starts at k (0 < k < last) where k's acceleration is not k − 1's: only the changed
    // points and the one after them can start or stop starting one, and, when the change reaches
    // the path's end, the point before it, which may become the last (no start) or stop being it.
    const bool reaches_end = change.first + change.removed >= old_count;
    const std::size_t recheck_first =
        std::max<std::size_t>(reaches_end && change.first > 0 ? change.first - 1 : change.first, 1);
    std::size_t first = 0;
    const auto start_span = [&](std::size_t start) {
        spans.push_back({first, start, acceleration(first)});
        first = start;
    };
    for (const AccelerationSpan& span : before)
        if (span.first_point > 0 && span.first_point < recheck_first)
            start_span(span.first_point);
    for (std::size_t k = recheck_first; k <= std::min(changed_end, last - 1); ++k)
        if (acceleration(k) != acceleration(k - 1))
            start_span(k);
    for (const AccelerationSpan& span : before)
        if (span.first_point > change.first + change.removed)
            start_span(span.first_point - change.removed + change.inserted);
    spans.push_back({first, last, acceleration(first)});
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

void evaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                   Refinement refinement)
{
    kb_segments(points, settings.slopes, path.curve.segments);
    sample_curve(path.curve, settings.samples_per_segment);
    path.segments_unmade = {};
    if (settings.spacing == Spacing::exact && refinement == Refinement::in_steps) {
        path.arc_lengths.mark_all(path.curve.segments);
        path.inbetweens_current = false;
        return;
    }
    if (settings.spacing == Spacing::exact)
        path.arc_lengths.measure(path.curve.segments);
    else
        path.arc_lengths = {};
    place_inbetweens(points, settings, path);
}

bool make_room(EvaluatedPath& path, std::size_t control_points, std::size_t most_segments)
{
    SampledCurve& curve = path.curve;
    const std::size_t segments = control_points < 2 ? 0 : control_points - 1;
    if (curve.segments.size() < segments) {
        curve.segments.reserve(segments);
        curve.segments.resize(std::min(segments, curve.segments.size() + std::max<std::size_t>(most_segments, 1)));
        if (curve.segments.size() < segments)
            return false;
    }
    curve.segment_length.resize(std::max(curve.segment_length.size(), segments));
    curve.length_to_point.resize(std::max(curve.length_to_point.size(), segments == 0 ? 0 : segments + 1));
    return true;
}

bool has_room(const EvaluatedPath& path, std::size_t control_points)
{
    const std::size_t segments = control_points < 2 ? 0 : control_points - 1;
    const SampledCurve& curve = path.curve;
    return curve.segments.size() >= segments && curve.segment_length.size() >= segments &&
           curve.length_to_point.size() >= (segments == 0 ? 0 : segments + 1);
}

void place_inbetweens(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path)
{
    place_inbetweens_on(acceleration_spans(points), points, settings, path);
}

namespace {

// Whether control points first … last still have the accelerations of the spans `timings` were
// placed on: then a key on them leaves the spans as they were, and the 10^6 points' accelerations
// need not be read again. Spans cover the points as [first_point, last_point).
bool same_accelerations(std::span<const ControlPoint> points, const std::vector<SpanTiming>& timings,
                        std::size_t first, std::size_t last)
{
    if (timings.empty())
        return false;
    auto span = std::upper_bound(timings.begin(), timings.end(), first,
                                 [](std::size_t point, const SpanTiming& timing) { return point < timing.span.first_point; });
    if (span == timings.begin())
        return false;
    --span;
    for (std::size_t k = first; k <= last && k + 1 < points.size(); ++k) {
        while (span != timings.end() && k >= span->span.last_point)
            ++span;
        if (span == timings.end() || limits::staff_value.clamp(points[k].staff.acceleration) != span->span.acceleration)
            return false;
    }
    return true;
}

std::vector<AccelerationSpan> spans_of(const std::vector<SpanTiming>& timings)
{
    std::vector<AccelerationSpan> spans;
    spans.reserve(timings.size());
    for (const SpanTiming& timing : timings)
        spans.push_back(timing.span);
    return spans;
}

// Consecutive frames at one point (SPEC §4.3): KEY1, the in-betweens and KEY2 in order.
void list_frozen_frames(EvaluatedPath& path)
{
    Vec3 previous = path.curve.sample(0);
    for (std::size_t j = 0; j < path.inbetweens.size(); ++j) {
        if (path.inbetweens[j].position == previous)
            path.frozen_frames.push_back(j);
        previous = path.inbetweens[j].position;
    }
    if (previous == path.curve.sample(path.curve.sample_count() - 1))
        path.frozen_frames.push_back(path.inbetweens.size());
}

// A path of zero length (a point that stays) still has a pace: its in-betweens progress by the
// first control point's law over one span, so that surface fitting never sees a neighbour stand
// still and then jump (SPEC §5.3).
void place_on_one_point(std::span<const ControlPoint> points, int inbetween_count, EvaluatedPath& path)
{
    for (int j = 1; j <= inbetween_count; ++j) {
        const double tau = static_cast<double>(j) / (inbetween_count + 1);
        path.inbetweens.push_back(
            {path.curve.segments.front().start, acceleration_distance_fraction(tau, points.front().staff.acceleration), 0});
    }
}

} // namespace

void place_inbetweens_on(std::vector<AccelerationSpan> spans, std::span<const ControlPoint> points,
                         const PathSettings& settings, EvaluatedPath& path)
{
    path.inbetweens.clear();
    path.span_timings.clear();
    path.frozen_frames.clear();
    path.inbetweens_current = true;
    if (path.curve.segments.empty())
        return;
    const int inbetween_count = std::max(settings.inbetween_count, 0);
    const bool exact = settings.spacing == Spacing::exact;
    const std::span<const HermiteSegment> segments = path.curve.segments;
    CurveArcLengths& arc_lengths = path.arc_lengths;
    if (exact && arc_lengths.segment_count() != segments.size())
        arc_lengths.measure(segments);
    else if (exact && arc_lengths.pending())
        arc_lengths.measure_pending(segments, segments.size());
    // Distance from the curve's start to control point k, in the measure the spacing uses.
    const auto boundary = [&](std::size_t control_point) {
        return exact ? arc_lengths.length_to_segment_start(control_point) : path.curve.length_to_point[control_point];
    };
    const double total = exact ? arc_lengths.total_length() : path.curve.total_length();

    path.inbetweens.reserve(static_cast<std::size_t>(inbetween_count));
    if (!(total > 0.0))
        return place_on_one_point(points, inbetween_count, path);

    std::vector<double> span_lengths;
    for (const AccelerationSpan& span : spans)
        span_lengths.push_back(boundary(span.last_point) - boundary(span.first_point));
    const std::vector<int> shares = share_by_largest_remainder(span_lengths, inbetween_count);

    // The targets rise along the path: one walk over the samples finds all their nearest samples.
    NearestSamples nearest_sample(path.curve);
    for (std::size_t s = 0; s < spans.size(); ++s) {
        const double start = boundary(spans[s].first_point);
        path.span_timings.push_back({spans[s], start / total, span_lengths[s] / total, path.inbetweens.size(),
                                     static_cast<std::size_t>(shares[s])});
        for (const double target : span_targets(start, span_lengths[s], shares[s], spans[s].acceleration)) {
            Inbetween shown;
            if (exact) {
                shown.position = curve_point_at(segments, arc_lengths.parameter_at(segments, target));
                shown.arc_fraction = target / total;
                const double chord_target = shown.arc_fraction * path.curve.total_length();
                shown.sample_index = nearest_sample(chord_target).sample;
            } else {
                const NearestSamples::Found found = nearest_sample(target);
                shown.sample_index = found.sample;
                shown.position = path.curve.sample(shown.sample_index);
                shown.arc_fraction = found.chord_length / total;
            }
            path.inbetweens.push_back(shown);
        }
    }
    list_frozen_frames(path);
}

std::string describe_frozen_frames(const EvaluatedPath& path, std::size_t most_named)
{
    const std::size_t key2 = path.inbetweens.size() + 1;
    const auto frame_name = [key2](std::size_t frame) {
        return frame == 0 ? std::string("KEY1") : frame == key2 ? std::string("KEY2") : std::to_string(frame);
    };
    std::string text;
    const std::size_t named = std::min(most_named, path.frozen_frames.size());
    for (std::size_t i = 0; i < named; ++i) {
        const std::size_t frame = path.frozen_frames[i];
        text += (i == 0 ? "" : ", ") + frame_name(frame) + "=" + frame_name(frame + 1);
    }
    if (named < path.frozen_frames.size())
        text += " and " + std::to_string(path.frozen_frames.size() - named) + " more";
    return text;
}

namespace {

// Segment s runs from control point s to s + 1 and its tangents read points s − 1 … s + 2: the
// segments whose window meets the changed points are made again, in the numbering before the
// change and after it.
SegmentSplice segments_touched(const PathChange& change, std::size_t old_segments, std::size_t new_segments)
{
    const std::size_t first = change.first >= 2 ? change.first - 2 : 0;
    return {first, std::min(change.first + change.removed + 1, old_segments) - first,
            std::min(change.first + change.inserted + 1, new_segments) - first};
}

bool change_fits(std::span<const ControlPoint> points, const PathSettings& settings, const EvaluatedPath& path,
                 const PathChange& change)
{
    const SampledCurve& curve = path.curve;
    const std::size_t old_points = curve.segments.size() + 1;
    const bool exact = settings.spacing == Spacing::exact;
    return points.size() >= 2 && !curve.segments.empty() &&
           curve.samples_per_segment == std::max(settings.samples_per_segment, 1) &&
           curve.segment_length.size() == curve.segments.size() && change.first + change.removed <= old_points &&
           old_points - change.removed + change.inserted == points.size() &&
           (!exact || path.arc_lengths.segment_count() == curve.segments.size());
}

// Makes and measures the touched segments after the curve's arrays were spliced; a segment that
// came out as it was is not measured again. Returns the first whose chord length changed (end if
// none). Each half of a global change of 10^6 control points runs on a core of its own.
std::size_t remake_segments(std::span<const ControlPoint> points, const PathSettings& settings, SampledCurve& curve,
                            std::size_t first, std::size_t end)
{
    std::array<std::size_t, 2> changed_first{end, end};
    split_across_cores(end - first, 4096, [&](std::size_t from, std::size_t to) {
        // Kept here and stored once: the halves' entries share a cache line.
        std::size_t half_first = end;
        SegmentMeasure measure(curve.basis);
        for (std::size_t s = first + from; s < first + to; ++s) {
            const HermiteSegment segment = kb_segment(points, settings.slopes, s);
            if (segment == curve.segments[s])
                continue;
            curve.segments[s] = segment;
            curve.segment_length[s] = measure(segment);
            half_first = std::min(half_first, s);
        }
        changed_first[from == 0 ? 0 : 1] = half_first;
    });
    return std::min(changed_first[0], changed_first[1]);
}

// Segments `unmade` (in the numbering before `change`) and those `change` touched, in the numbering
// after it: one range holding both.
SegmentRange joined(const SegmentRange& unmade, const SegmentSplice& change)
{
    const SegmentRange touched{change.first, change.new_end()};
    if (unmade.empty())
        return touched;
    return {std::min(change.moved(unmade.first, false), touched.first),
            std::max(change.moved(unmade.end, true), touched.end)};
}

// Makes up to `most` of the segments left unmade, in path order, and adds up the lengths: within
// those made while some are left (the lengths before them are current), to the curve's end once
// none is.
void make_unmade_segments(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                          std::size_t most)
{
    SegmentRange& unmade = path.segments_unmade;
    const std::size_t first = unmade.first;
    const std::size_t end = first + std::min(most, unmade.size());
    remake_segments(points, settings, path.curve, first, end);
    unmade.first = end;
    if (!unmade.empty())
        return add_up_lengths(path.curve, first, end);
    unmade = {};
    add_up_lengths(path.curve, first);
}

SegmentSplice evaluated_afresh(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                               Refinement refinement = Refinement::at_once)
{
    const std::size_t old_segments = path.curve.segments.size();
    evaluate_path(points, settings, path, refinement);
    return {0, old_segments, path.curve.segments.size()};
}

} // namespace

SegmentSplice reevaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                              const PathChange& change, Refinement refinement)
{
    const std::size_t old_segments = path.curve.segments.size();
    if (!change_fits(points, settings, path, change))
        return evaluated_afresh(points, settings, path, refinement);
    const bool in_steps = refinement == Refinement::in_steps;
    const bool exact = settings.spacing == Spacing::exact;
    const bool same_count = change.removed == change.inserted;
    // The spans placed last are those of the points only when the in-betweens are current (read
    // before anything here changes them).
    const auto place = [&, were_current = path.inbetweens_current] {
        const bool spans_kept =
            same_count && change.inserted > 0 && were_current &&
            same_accelerations(points, path.span_timings, change.first, change.first + change.inserted - 1);
        // Spans placed on the points before the change are read around it alone (a waypoint edit).
        const bool spans_known = were_current && !path.span_timings.empty();
        place_inbetweens_on(spans_kept    ? spans_of(path.span_timings)
                            : spans_known ? acceleration_spans_after(spans_of(path.span_timings), points, change)
                                          : acceleration_spans(points),
                            points, settings, path);
    };
    if (change.what == PathChange::What::accelerations) {
        if (in_steps && (exact || !path.segments_unmade.empty())) {
            path.inbetweens_current = false;
            return {change.first, 0, 0};
        }
        if (!path.segments_unmade.empty())
            make_unmade_segments(points, settings, path, path.segments_unmade.size());
        place();
        return {change.first, 0, 0};
    }
    const SegmentSplice touched = segments_touched(change, old_segments, points.size() - 1);
    SampledCurve& curve = path.curve;
    splice_room(curve.segments, touched);
    splice_room(curve.segment_length, touched);
    curve.length_to_point.resize(curve.segments.size() + 1);
    const bool had_unmade = !path.segments_unmade.empty();
    const SegmentRange to_make = joined(path.segments_unmade, touched);
    path.segments_unmade = {};
    if (in_steps && exact)
        path.arc_lengths.mark_changed(curve.segments, touched);
    // In steps, a change of values (a global key's 10^6 segments) makes none: its first picture waits
    // for nothing but the key.
    if (in_steps && same_count) {
        path.segments_unmade = to_make;
        path.inbetweens_current = false;
        return touched;
    }
    const std::size_t changed = remake_segments(points, settings, curve, to_make.first, to_make.end);
    if (!same_count || had_unmade)
        add_up_lengths(curve, to_make.first);
    else if (changed < to_make.end)
        add_up_lengths(curve, changed);
    if (in_steps) {
        path.inbetweens_current = false;
        return touched;
    }
    if (exact)
        path.arc_lengths.remeasure(curve.segments, touched);
    place();
    return touched;
}

SegmentSplice reevaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                              std::size_t first_changed, std::size_t last_changed)
{
    if (first_changed > last_changed || first_changed >= points.size())
        return evaluated_afresh(points, settings, path);
    const std::size_t count = std::min(last_changed, points.size() - 1) - first_changed + 1;
    return reevaluate_path(points, settings, path, PathChange{first_changed, count, count, PathChange::What::staff});
}

bool refine_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                 std::size_t most_segments)
{
    if (path.inbetweens_current)
        return true;
    if (!path.segments_unmade.empty()) {
        make_unmade_segments(points, settings, path, most_segments);
        // Arc lengths are measured in steps of their own.
        if (!path.segments_unmade.empty() || path.arc_lengths.pending())
            return false;
    }
    if (path.arc_lengths.pending()) {
        path.arc_lengths.measure_pending(path.curve.segments, most_segments);
        if (path.arc_lengths.pending())
            return false;
    }
    place_inbetweens(points, settings, path);
    return true;
}

} // namespace apcs
