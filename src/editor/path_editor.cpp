#include "apcs/editor/path_editor.h"

#include "apcs/animation/curve_move.h"
#include "apcs/animation/input_limits.h"
#include "apcs/animation/kochanek_bartels.h"
#include "apcs/base/overloaded.h"
#include "apcs/screens/path_overlays.h"
#include "apcs/screens/reference_curve.h"
#include "apcs/raster/screen_layout.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <utility>

namespace apcs {

namespace {

// A segment of the curve before a staff key, with its index: one the key may move (on a long
// region every stride-th of them), to say how far the key moved the curve.
struct SegmentBeforeKey {
    std::size_t index = 0;
    HermiteSegment before;
};

// Keys add multiples of the step; rounding to 1e-9 keeps repeated steps from drifting.
double snapped(double value) { return limits::staff_value.clamp(std::round(value * 1e9) / 1e9); }

enum class KeyFrames { shown, hidden };

// What the view keeps in sight: the path, its control points, and both key frames while K shows them.
ViewScene shown_scene(const PathEditor::Options& options, const ControlPoints& points, const EvaluatedPath& path,
                      KeyFrames key_frames)
{
    PathScreenContent shown = path_screen_content(points, path);
    if (key_frames == KeyFrames::shown)
        shown.key_frame_polylines = options.key_frame_polylines;
    return path_screen_scene(shown);
}

// The middle of a region's control points (world), where Z magnifies.
Vec3 region_middle(const ControlPoints& points, ControlRegion region)
{
    BoundingBox box;
    for (std::size_t k = region.first; k <= region.last && k < points.size(); ++k)
        box.add(points[k].position);
    return box.centre();
}

// How far a staff key moved the curve at most: in world units, and in raster pixels of the view
// shown (the larger of the x and y distances: the pixel steps a point of the curve went).
struct CurveMove {
    double world = 0.0;
    double pixels = 0.0;
};

// A region of more than this many segments is measured at as many, evenly spread: the exact
// search costs about 2 µs a segment, and a global key on 10^6 control points must stay near its
// 80 ms. The move said is then that of the segments measured.
constexpr std::size_t most_measured_segments = 4096;

// The segments whose tangents the region's points can set (ends included) as they were before a
// key gave the region new staff values: each made from the points around it (kb_segment reads
// points k − 1 … k + 2) with the region's values taken back from the runs the key replaced. Made
// from the points, not read from the curve: the curve's own may wait for a refinement in steps.
std::vector<SegmentBeforeKey> segments_before_key(std::span<const ControlPoint> points, EndSlopes slopes,
                                                  ControlRegion region, const std::vector<StaffRun>& runs_before)
{
    std::vector<std::size_t> run_ends; // the point after each run
    for (std::size_t end = region.first; const StaffRun& run : runs_before)
        run_ends.push_back(end += run.count);
    const auto staff_before = [&](std::size_t point) {
        const auto run = std::upper_bound(run_ends.begin(), run_ends.end(), point) - run_ends.begin();
        return runs_before[static_cast<std::size_t>(run)].staff;
    };
    const std::size_t first = region.first < 2 ? 0 : region.first - 2;
    const std::size_t end = std::min(points.size() - 1, region.last + 2);
    const std::size_t count = end > first ? end - first : 0;
    const std::size_t stride = std::max<std::size_t>(1, (count + most_measured_segments - 1) / most_measured_segments);
    std::vector<SegmentBeforeKey> measured;
    const std::size_t runs_end = run_ends.empty() ? region.first : run_ends.back();
    for (std::size_t index = first; index < end; index += stride) {
        const std::size_t window_first = index == 0 ? 0 : index - 1;
        const std::size_t window_size = std::min(points.size(), index + 3) - window_first;
        std::array<ControlPoint, 4> window{};
        for (std::size_t k = 0; k < window_size; ++k) {
            window[k] = points[window_first + k];
            if (region.contains(window_first + k) && window_first + k < runs_end)
                window[k].staff = staff_before(window_first + k);
        }
        measured.push_back({index, kb_segment(std::span(window.data(), window_size), slopes, index - window_first)});
    }
    return measured;
}

// `before` as segments_before_key made them, `points` those after the key. The pixels are
// measured at each segment's furthest-moved sample (SampleMove), not at every sample: one
// projection pair per segment; a view seen nearly along the move may show another sample moved a
// pixel more. Segments that cannot beat the furthest move found are not searched.
CurveMove curve_move(std::span<const SegmentBeforeKey> before, std::span<const ControlPoint> points, EndSlopes slopes,
                     std::span<const HermiteBasis> basis, const ViewTransform& view)
{
    CurveMove moved;
    for (const SegmentBeforeKey& segment : before) {
        const HermiteSegment after = kb_segment(points, slopes, segment.index);
        const SampleMove sample = furthest_sample_move(segment.before, after, basis, moved.world);
        if (sample.distance <= 0.0)
            continue;
        moved.world = std::max(moved.world, sample.distance);
        const DevicePoint was = view.to_device(sample.before);
        const DevicePoint is = view.to_device(sample.after);
        moved.pixels = std::max({moved.pixels, std::abs(is.x - was.x), std::abs(is.y - was.y)});
    }
    return moved;
}

// "0.024", "0.0012", "1.25": two significant digits below 1, two decimals above.
std::string world_distance_text(double distance)
{
    char text[32];
    std::snprintf(text, sizeof text, distance < 1.0 ? "%.2g" : "%.2f", distance);
    return text;
}

// SPEC §7.2.1: "moved up to 0.024 = 1 px"; a move under half a pixel is "under 1 px".
std::string curve_move_text(const CurveMove& moved)
{
    if (moved.world <= 0.0)
        return "the curve did not move";
    const long pixels = std::lround(moved.pixels);
    return "moved up to " + world_distance_text(moved.world) + " = " +
           (pixels == 0 ? std::string("under 1 px") : std::to_string(pixels) + " px");
}

// "1 change", "3 changes".
std::string changes_text(std::size_t count) { return std::to_string(count) + (count == 1 ? " change" : " changes"); }

} // namespace

PathEditor::PathEditor(Setup setup, StepLog& log)
    : m_options(std::move(static_cast<Options&>(setup)))
    , m_log(log)
    , m_document(std::make_unique<PathDocument>(std::move(setup.points)))
    , m_picture(std::make_unique<PathPicture>(*m_document, m_options.settings, m_options.refinement,
                                              std::move(setup.evaluation_room)))
{
    assert(points().size() >= 2);
    fit_view();
}

void PathEditor::enter(Mode mode)
{
    m_mode = std::move(mode);
    changed();
}

// A staff key's move not measured yet was never shown: the text before leaves it out as the
// screen did.
template <typename Change>
void PathEditor::saying(Change change)
{
    const std::string said = message(MoveText::left_unmeasured);
    change();
    if (message(MoveText::left_unmeasured) != said)
        changed();
}

// Initial_Graphics fits the view to the path (SPEC §7.2.1: filled); it stays fixed while the staff
// or the waypoint editor changes the path, so that each key's effect is seen against a still
// picture, and is fitted again when they are left.
void PathEditor::fit_view()
{
    const KeyFrames key_frames = m_show_key_frames ? KeyFrames::shown : KeyFrames::hidden;
    m_fitted_view = shown_scene(m_options, points(), evaluated(), key_frames).fill(m_options.view_angles, layout::view_area);
    // The arrows keep the fitted view's scale: Z magnifies them with the curve.
    m_tangent_scale = tangent_arrow_scale(points(), *m_fitted_view);
    show_view();
}

void PathEditor::show_view()
{
    const double factor = static_cast<double>(1 << m_zoom_level);
    m_picture->set_view(m_zoom_level == 0 ? *m_fitted_view : m_fitted_view->zoomed(factor, m_zoom_about, layout::view_area));
}

// Z: ×2, ×4, ×8, then the fitted view again; about the picked region, or the path's middle.
bool PathEditor::zoom()
{
    m_zoom_level = next_zoom_level(m_zoom_level);
    const std::optional<ControlRegion> region = picked_region();
    // The path's middle: the sample halfway along the curve.
    const SampledCurve& curve = m_picture->evaluated().curve;
    std::string about = "the path's middle";
    m_zoom_about.reset();
    if (curve.sample_count() > 0)
        m_zoom_about = curve.sample(curve.nearest_sample(curve.total_length() / 2.0));
    if (region && !region->is_whole(points())) {
        m_zoom_about = region_middle(points(), *region);
        about = region->first == region->last ? "control point " + std::to_string(region->first + 1)
                                              : "control points " + std::to_string(region->first + 1) + " to " +
                                                    std::to_string(region->last + 1);
    }
    show_view();
    m_notice = m_zoom_level == 0 ? "zoom off: the view fitted to the path"
                                 : "zoom ×" + std::to_string(1 << m_zoom_level) + " about " + about + " (Z: more)";
    return true;
}

PathEditor::State PathEditor::leaf() const
{
    return std::visit(Overloaded{
                          [](const ControlChoice&) { return State::control_choice; },
                          [](const RegionPick& pick) { return pick.first ? State::region_last : State::region_first; },
                          [](const Staff& staff) { return staff.field ? State::value_field : State::staff; },
                          [](const Waypoints&) { return State::waypoints; },
                          [](const AskAgain&) { return State::ask_again; },
                      },
                      m_mode);
}

// Only an accepted path is written: the editor is then asking whether to adjust again.
void PathEditor::show_problem(const std::string& message)
{
    saying([&] {
        m_problem = message;
        if (!std::holds_alternative<AskAgain>(m_mode))
            enter(AskAgain{ControlRegion::whole(points()), points().front().staff});
    });
}

namespace {

// A change of the path is added to what is left of the picture; 8 and 2 only open the staff or the
// region's pick over it (an opened long path's arc lengths are measured meanwhile). Any other key
// acts on the finished picture.
bool leaves_refinement_running(const Command& command)
{
    return std::holds_alternative<command::StaffStep>(command) || std::holds_alternative<command::MovePoint>(command) ||
           std::holds_alternative<command::InsertPoint>(command) || std::holds_alternative<command::DeletePoint>(command) ||
           std::holds_alternative<command::ChooseGlobal>(command) || std::holds_alternative<command::ChooseLocal>(command);
}

} // namespace

void PathEditor::refine_step()
{
    m_picture->refine_step();
    measure_move_when_refined();
}

void PathEditor::refine()
{
    m_picture->refine();
    measure_move_when_refined();
}

void PathEditor::measure_move_when_refined() const
{
    if (!m_move_unmeasured || m_picture->refining())
        return;
    const auto& key = std::get<StaffEdit>(m_document->edits()[*m_move_unmeasured]);
    const std::vector<SegmentBeforeKey> before =
        segments_before_key(points(), m_options.settings.slopes, key.region, key.points_before);
    m_moved = curve_move_text(curve_move(before, points(), m_options.settings.slopes,
                                         m_picture->evaluated().curve.basis, m_picture->view()));
    m_move_unmeasured.reset();
}

PathEditor::Outcome PathEditor::update(const Command& command)
{
    if (!leaves_refinement_running(command))
        refine();
    const Outcome outcome = take_command(command);
    // The waypoint editor boxes its chosen point in the picture it holds.
    if (!std::holds_alternative<Waypoints>(m_mode))
        m_picture->box_region(picked_region());
    return outcome;
}

// lager's update through the chart: the row the command meets in the editor's leaf acts on the
// mode and says which follows (path_editor_chart.cpp).
PathEditor::Outcome PathEditor::take_command(const Command& command)
{
    m_accepted = false;
    saying([&] {
        // What the last key said is said once.
        m_notice.clear();
        m_moved.clear();
        m_move_unmeasured.reset();
        chart().fire(*this, command, [](const PathEditor& editor) { return editor.leaf(); });
    });
    return m_accepted ? Outcome::accepted : Outcome::editing;
}

// K fits the view to the path and the key frames together, or to the path alone again (the
// waypoint editor's view stays until it is left: its own row).
void PathEditor::toggle_key_frames()
{
    m_show_key_frames = !m_show_key_frames;
    changed();
    if (!std::holds_alternative<Waypoints>(m_mode))
        fit_view();
}

void PathEditor::toggle_ghost()
{
    m_show_ghost = !m_show_ghost;
    changed();
    m_notice = !m_show_ghost              ? "ghost hidden (O shows it)"
               : m_picture->has_ghost() ? "ghost shown: the curve before the last change, dotted"
                                        : "ghost shown after the next staff key or waypoint edit";
}

void PathEditor::choose_tangent_point(const command::ChoosePoint& choose)
{
    const std::size_t chosen = wrapped_point(m_tangent_point, choose.by, points().size());
    // Only T shows the point (its arrows and numbers).
    if (chosen != m_tangent_point && m_show_tangents)
        changed();
    m_tangent_point = chosen;
}

// C pins the curve as it is, labelled with the staff's values as they are (the region's, else the
// first control point's, which the staff shows then), or unpins the one pinned.
void PathEditor::pin_or_unpin_reference()
{
    if (m_picture->has_reference()) {
        m_picture->unpin_reference();
        m_notice = "reference A unpinned (C pins the curve as it is)";
        return;
    }
    const std::string label = reference_label(region_staff().value_or(points().front().staff));
    m_picture->pin_reference(label);
    // A label of all four values leaves the message line room for less.
    const std::string said = label + " pinned, dashed: under the curve till it moves (C unpins)";
    m_notice = fits_message_line(said) ? said : label + " pinned, dashed (C unpins)";
}

// The arrow's first move, whichever way, brings it from the corner to the first point.
void PathEditor::move_arrow(const command::ArrowMove& move)
{
    RegionPick& pick = std::get<RegionPick>(m_mode);
    const std::size_t last_index = points().size() - 1;
    const auto target = pick.arrow ? static_cast<long long>(*pick.arrow) + move.points : 0LL;
    const auto arrow = static_cast<std::size_t>(std::clamp<long long>(target, 0, static_cast<long long>(last_index)));
    if (pick.arrow != arrow)
        changed();
    pick.arrow = arrow;
}

// Enter at the region's last point, the arrow at or after the first (Enter twice on one control
// point picks it alone: KB's per-key control).
void PathEditor::pick_last_point()
{
    const RegionPick pick = std::get<RegionPick>(m_mode);
    const std::size_t first = *pick.first;
    const std::size_t last = *pick.arrow;
    m_problem.clear();
    m_log.log(last == first ? "local control: control point " + std::to_string(first + 1)
                            : "local control: control points " + std::to_string(first + 1) + " to " +
                                  std::to_string(last + 1));
    enter(start_staff({first, last}));
}

PathEditor::Staff PathEditor::start_staff(ControlRegion region)
{
    assert(region.first <= region.last && region.last < points().size());
    m_picture->drop_ghost(); // a new region starts without one
    Staff staff{region, points()[region.first].staff, StaffLine::tension, 0.0, std::nullopt};
    staff.line_start_value = staff.staff[staff.line];
    m_tangent_point = region.is_whole(points()) ? 1 : region.first;
    return staff;
}

// Every value that changes a point is one change for undo; a key that changes nothing (a step
// past the end of the line) is not.
void PathEditor::set_staff_value(Staff& staff, double value)
{
    StaffEdit edit{staff.region, staff.line, staff.staff, staff.line_start_value, {}};
    staff.staff[staff.line] = snapped(value);
    const std::optional<PathChange> change = m_document->set_staff(std::move(edit), staff.staff);
    if (!change)
        return;
    // An acceleration moves no segment.
    if (change->what == PathChange::What::accelerations) {
        m_moved = "only the in-betweens moved";
        return;
    }
    m_move_unmeasured = m_document->edit_count() - 1;
}

// A single control point starts no span of its own: its acceleration line is skipped.
bool PathEditor::staff_line_is_last() const
{
    const Staff& staff = std::get<Staff>(m_mode);
    const bool single_point = staff.region.first == staff.region.last;
    return is_last_staff_line(staff.line) || (single_point && staff.line == StaffLine::bias);
}

// Enter or Esc on a staff line: its value logged, then the next line, or the question whether to
// adjust again after the last.
void PathEditor::end_staff_line(LineEnding ending)
{
    Staff& staff = std::get<Staff>(m_mode);
    const bool kept = ending == LineEnding::kept;
    if (kept) {
        set_staff_value(staff, staff.line_start_value);
        m_moved.clear(); // the next line is named, not how far going back moved the curve
        m_move_unmeasured.reset();
    }
    m_log.log(std::string(staff_line_name(staff.line)) + " " + format_staff_value(staff.staff[staff.line]) +
              (kept ? " (kept)" : ""));
    m_picture->drop_ghost(); // the ghost lasts until the next line
    if (staff_line_is_last()) {
        enter(AskAgain{staff.region, staff.staff});
        return;
    }
    changed();
    staff.line = next_staff_line(staff.line);
    staff.line_start_value = staff.staff[staff.line];
}

// "=" and Enter on a number: the typed value sets the line like keys would; the line stays active.
void PathEditor::set_typed_value()
{
    Staff& staff = std::get<Staff>(m_mode);
    staff.field->submit();
    set_staff_value(staff, staff.field->value());
    const std::string line(staff_line_name(staff.line));
    m_log.log(line + " typed " + format_staff_value(staff.staff[staff.line]));
    if (staff.field->clamped())
        m_notice = line + " set to " + format_staff_value(staff.staff[staff.line]) + ": the staff runs from -1 to 1";
    staff.field.reset();
    changed();
}

void PathEditor::say_nothing_to_undo() { m_notice = "Nothing to undo: the path is as it was opened"; }

bool PathEditor::last_edit_is_staff() const
{
    return m_document->edit_count() > 0 && std::holds_alternative<StaffEdit>(m_document->edits().back());
}

// U with a change to take back: the last one, whichever it is. The picture takes the change back
// as it is next read: only the segments the change's points shape are sampled again (a path of
// 10^6 control points stays interactive), and the ghost is the path with the change.
void PathEditor::undo()
{
    const PathEdit change = m_document->undo();
    m_problem.clear();
    std::visit([this](const auto& last) { undone(last); }, change);
    m_notice += "; " + changes_text(m_document->edit_count()) + " left to undo";
    m_log.log(m_notice);
}

// Back to the staff line the change was made on, with the staff as it was.
void PathEditor::undone(const StaffEdit& change)
{
    m_notice = "Undone: " + std::string(staff_line_name(change.line)) + " back to " +
               format_staff_value(change.staff[change.line]);
    enter(Staff{change.region, change.staff, change.line, change.line_start_value, std::nullopt});
}

// A waypoint edit is undone at the choice of control, where the editor was opened.
void PathEditor::undone(const WaypointChange& change)
{
    const std::string point = "control point " + std::to_string(change.index + 1);
    switch (change.kind) {
    case WaypointChange::Kind::insert: m_notice = "Undone: the insertion of " + point; break;
    case WaypointChange::Kind::remove: m_notice = "Undone: the deletion of " + point; break;
    case WaypointChange::Kind::move: m_notice = "Undone: the move of " + point; break;
    }
    m_tangent_point = std::min(m_tangent_point, points().size() - 1);
    fit_view();
    enter(ControlChoice{});
}

PathEditor::Waypoints PathEditor::open_waypoints()
{
    m_log.log("waypoint editor");
    const double step = waypoint_step(shown_scene(m_options, points(), evaluated(), KeyFrames::shown).bounds());
    return Waypoints{WaypointEditor(*m_document, *m_picture, {m_picture->view(), step})};
}

// Enter keeps the waypoint editor's changes, Esc takes them back (the path as it was when the
// editor opened): either way the choice of control follows.
void PathEditor::leave_waypoints(WaypointsLeft left)
{
    WaypointEditor& editor = waypoint_editor();
    const std::size_t changes = editor.change_count();
    if (left == WaypointsLeft::changes_kept) {
        m_notice = "Waypoints: " + changes_text(changes) + " kept, " + std::to_string(points().size()) +
                   " control points";
    } else {
        editor.discard();
        m_notice = "Waypoints: " + changes_text(changes) + " undone";
    }
    m_log.log(m_notice);
    m_tangent_point = std::min(m_tangent_point, points().size() - 1);
    enter(ControlChoice{});
}

std::optional<StaffValues> PathEditor::region_staff() const
{
    if (const auto* staff = std::get_if<Staff>(&m_mode))
        return staff->staff;
    if (const auto* asked = std::get_if<AskAgain>(&m_mode))
        return asked->staff;
    return std::nullopt;
}

std::optional<StaffLine> PathEditor::staff_line() const
{
    if (const auto* staff = std::get_if<Staff>(&m_mode))
        return staff->line;
    return std::nullopt;
}

} // namespace apcs
