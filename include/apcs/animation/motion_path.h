#pragma once

#include "apcs/animation/arc_length.h"
#include "apcs/animation/control_point.h"
#include "apcs/animation/path_change.h"
#include "apcs/animation/hermite.h"
#include "apcs/animation/sampled_curve.h"

#include <span>
#include <string>
#include <vector>

namespace apcs {

// How the shown in-betweens are placed on the curve (SPEC §4.3): `nearest` takes the sample
// nearest to each target chord length (the thesis' method), `exact` inverts the arc length.
enum class Spacing { nearest, exact };

struct PathSettings {
    EndSlopes slopes;
    int samples_per_segment = 32;
    int inbetween_count = 12;
    Spacing spacing = Spacing::nearest;
};

// A run of control points sharing one acceleration (SPEC §2.1): it starts at first_point and
// runs on to the next control point whose acceleration differs (last_point). Accelerations are
// clamped to [-1, 1] (limits::staff_value) before they are compared, so 3 and 1 share a span.
struct AccelerationSpan {
    std::size_t first_point = 0;
    std::size_t last_point = 0;
    double acceleration = 0.0;
};

std::vector<AccelerationSpan> acceleration_spans(std::span<const ControlPoint> points);
// acceleration_spans(points) from `before`, the spans of the points before `change`: only the
// accelerations of the changed points and their neighbours are read (a waypoint edit on 10^5 points
// reads a few, not all).
std::vector<AccelerationSpan> acceleration_spans_after(std::span<const AccelerationSpan> before,
                                                      std::span<const ControlPoint> points, const PathChange& change);

// Shares `total` among parts in proportion to their weights by the largest remainder method
// (ties go to the earlier part). All-zero weights share equally.
std::vector<int> share_by_largest_remainder(std::span<const double> weights, int total);

struct Inbetween {
    Vec3 position;
    // Fraction of the whole path length reached here, in [0, 1] (chord length for `nearest`,
    // arc length for `exact`). A path of zero length progresses by its first control point's
    // acceleration law instead: law(j / (M + 1)) for in-between j.
    double arc_fraction = 0.0;
    // The curve sample shown (nearest spacing); for exact spacing the sample nearest to it.
    std::size_t sample_index = 0;
};

// How one acceleration span shares the path's time and length: where it starts and how long it
// is, as fractions of the whole path in the measure of the spacing (chord length for `nearest`,
// arc length for `exact`), and which in-betweens fall in it.
struct SpanTiming {
    AccelerationSpan span;
    double start_fraction = 0.0;
    double length_fraction = 0.0;
    std::size_t first_inbetween = 0;
    std::size_t inbetween_count = 0;
};

// One graphic point's path, evaluated: the KB segments, the sampled curve and the shown
// in-betweens (thesis DRAW, Cal_tangent_vector, Cal_INBETWEENS, Decide_Show_Inbetween).
struct EvaluatedPath {
    SampledCurve curve; // its segments, and how they are sampled
    // Exact spacing: the arc lengths of curve.segments, kept so that a change measures only the
    // segments it made again. Empty for nearest spacing.
    CurveArcLengths arc_lengths;
    std::vector<Inbetween> inbetweens;
    // The spans in path order (empty for a path of zero length or of fewer than two points).
    std::vector<SpanTiming> span_timings;
    // The frames that repeat ("freeze"): f in this list means frame f and frame f + 1 are one point,
    // frames numbered 0 (KEY1), 1 … M (the in-betweens), M + 1 (KEY2), in increasing order. With
    // nearest spacing two in-betweens can fall on one sample (more in-betweens than samples, or a
    // strong acceleration on a short span), or in-between 1 on KEY1's. Exact spacing never repeats
    // a position on a path of some length; a path of zero length, all one point by nature, lists none.
    std::vector<std::size_t> frozen_frames;
    bool frames_freeze() const { return !frozen_frames.empty(); }
    // False after a change evaluated with Refinement::in_steps under exact spacing, until
    // refine_path has measured the arc lengths it marked and placed the in-betweens on them: the
    // in-betweens, span timings and frozen frames are then those of an earlier state of the path.
    bool inbetweens_current = true;
    // Refinement::in_steps: segments whose control points a change of values or a point's move set
    // anew but which are not made yet (their chord lengths, the lengths after them, their arc lengths
    // and the in-betweens are those of an earlier state: inbetweens_current is false). refine_path
    // makes them first, in path order.
    SegmentRange segments_unmade;
};

// The frozen frames named as the animator counts them, "KEY1=1, 5=6, 12=KEY2" (in-betweens by the
// number of their inb file), at most `most_named` pairs and then "and K more".
std::string describe_frozen_frames(const EvaluatedPath& path, std::size_t most_named);

// Fewer than two control points give an empty path. Every input is clamped, never refused: the
// end slopes to [0, 1] (limits::end_slope), each control point's tension, continuity, bias and
// acceleration to [-1, 1] (limits::staff_value; see kb_segments and acceleration_spans), at least
// one sample per segment, no negative in-between count.
EvaluatedPath evaluate_path(std::span<const ControlPoint> points, const PathSettings& settings);
// The same into `path`, whose arrays keep their room: an editor that evaluates a long path at
// every key neither allocates nor faults in the pages of millions of samples again.
// With Refinement::in_steps and exact spacing the arc lengths are only marked to be measured and
// the in-betweens not placed (refine_path does both).
void evaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                   Refinement refinement = Refinement::at_once);
// The arrays evaluate_path fills for a path of `control_points` points, made ahead (their memory
// written once): evaluate_path then writes into them. A session makes them for a long path while
// its slopes prompt waits, so that opening it does not wait for the kernel's pages (on a virtual
// machine, memory new to the host took 1.2-2 ms a MB to touch: PERFORMANCE.md 19). One step makes
// up to `most_segments` segments' room (reserved whole first, so the made part never moves), the
// lengths' once the segments have theirs; returns has_room.
bool make_room(EvaluatedPath& path, std::size_t control_points, std::size_t most_segments);
// Whether `path` has that room, or more.
bool has_room(const EvaluatedPath& path, std::size_t control_points);
// `path` was evaluated from the points before `change` with `settings`; `points` are those after
// it. Only the segments whose tangents the changed points set are made and measured again (and
// their arc lengths, with exact spacing), the lengths after them added up again, and the
// in-betweens placed anew; segments after a change of the points' number are moved, not made. An
// acceleration changes no segment. The result is evaluate_path's, to the bit; arrays that do not
// fit the change, or a change outside the path, are evaluated afresh.
// Returns the segments it made again (all of them when evaluated afresh: removed = the old count).
// With Refinement::in_steps the in-betweens are not placed, and the rest waits for refine_path too:
// a change that keeps the number of segments (values, a point moved) makes none of them, they are
// marked unmade (with those a change before left); a change that inserts or removes a point makes
// its segments (and those left unmade) at once; with exact spacing the arc lengths of the segments
// touched are only marked (kept with those a change before marked and refine_path has not measured
// yet).
SegmentSplice reevaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                              const PathChange& change, Refinement refinement = Refinement::at_once);
// One step of what Refinement::in_steps left: up to `most_segments` segments made, or once all are,
// up to that many arc lengths measured, and once all are, the in-betweens placed. Returns whether the path is then as evaluate_path makes it (to
// the bit); `points` and `settings` are those of the last change.
bool refine_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                 std::size_t most_segments);
// The same for a change of staff values of control points first_changed … last_changed.
SegmentSplice reevaluate_path(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path,
                              std::size_t first_changed, std::size_t last_changed);
// The shown in-betweens of a path whose segments and curve are made (Cal_INBETWEENS,
// Decide_Show_Inbetween): the spans share them by length, each places its own by its law. All an
// acceleration changes: the editor calls it alone for a key on the ACCELERATION line.
void place_inbetweens(std::span<const ControlPoint> points, const PathSettings& settings, EvaluatedPath& path);
// The same on spans known to be acceleration_spans(points).
void place_inbetweens_on(std::vector<AccelerationSpan> spans, std::span<const ControlPoint> points,
                         const PathSettings& settings, EvaluatedPath& path);

} // namespace apcs
