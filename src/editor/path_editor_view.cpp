// What the path editor shows: the path screen of its step and the message line.
#include "apcs/editor/path_editor.h"

#include "apcs/base/overloaded.h"
#include "apcs/base/utf8.h"
#include "apcs/screens/path_overlays.h"
#include "apcs/screens/words.h"

namespace apcs {

namespace text = words;

namespace {

// The message line's text fits 79 columns (the 80th holds no text).
constexpr std::size_t max_message_width = 79;

} // namespace

bool fits_message_line(std::string_view text)
{
    return static_cast<std::size_t>(text_columns(text)) <= max_message_width;
}

namespace {

// "Adjust the path again ? (Y/N)" first, and beside it the goal, whole or in a few words, as it
// fits: the student sees whether to answer Y.
std::string question_with_goal(const GoalSaid& goal)
{
    for (const std::string_view said : {goal.feedback, goal.briefly}) {
        const std::string line = std::string(text::ask_again) + "   " + std::string(said);
        if (!said.empty() && fits_message_line(line))
            return line;
    }
    return std::string(text::ask_again);
}

} // namespace

// The tangents' numbers (T) stay, so that Tab is seen to choose a point; a pinned A under the
// curve is said after them where the line has room.
std::string PathEditor::with_reference_told(std::string numbers) const
{
    const std::string told = numbers + "  (A under the curve)";
    return m_picture->reference_under_curve() && fits_message_line(told) ? told : numbers;
}

std::string PathEditor::message(MoveText move) const
{
    if (!m_problem.empty())
        return m_problem;
    if (field_open()) {
        const Staff& staff = std::get<Staff>(m_mode);
        return staff.field->message(staff_line_name(staff.line));
    }
    if (!m_notice.empty())
        return m_notice;
    return std::visit(
        Overloaded{
            [](const ControlChoice&) { return std::string(text::choose_control); },
            [](const RegionPick& pick) { return std::string(pick.first ? text::pick_last : text::pick_first); },
            [&](const Staff& staff) {
                if (m_show_tangents)
                    return with_move(with_reference_told(tangent_numbers(evaluated().curve.segments, m_tangent_point)),
                                     staff, move);
                if (m_picture->reference_under_curve())
                    return std::string(text::reference_under_curve);
                return with_move(staff_message(staff), staff, move);
            },
            [](const Waypoints& waypoints) { return waypoints.editor.message(); },
            [](const AskAgain&) { return std::string(text::ask_again); },
        },
        m_mode);
}

// The 8/2 question stays while an opened path is finished (8 and 2 are taken meanwhile): what is
// still being done follows it in a few words.
std::string PathEditor::refining_message() const
{
    if (std::holds_alternative<ControlChoice>(m_mode) && m_notice.empty())
        return std::string(text::choose_control) + "    (" + m_picture->refining_words() + "...)";
    return m_picture->refining_message();
}

bool PathEditor::field_open() const
{
    const auto* staff = std::get_if<Staff>(&m_mode);
    return staff != nullptr && staff->field.has_value();
}

// After a staff key, how far it moved the curve (SPEC §7.2.1) follows what the line shows; when both
// do not fit, the line's name and the move, unless frames freeze: that warning matters more.
std::string PathEditor::with_move(const std::string& shown, const Staff& staff, MoveText move) const
{
    if (move == MoveText::measured)
        measure_move_when_refined();
    if (m_moved.empty())
        return shown;
    if (shown.size() + 2 + m_moved.size() <= max_message_width)
        return shown + "  " + m_moved;
    if (evaluated().frames_freeze())
        return shown;
    return m_options.path_name + ": " + std::string(staff_line_name(staff.line)) + "  " + m_moved;
}

std::string PathEditor::staff_message(const Staff& staff) const
{
    const std::string line(staff_line_name(staff.line));
    // A path of two control points has no interior one, where t, c and b act: say so, or the
    // animator sees nothing move and cannot tell why.
    if (points().size() == 2 && staff.line != StaffLine::acceleration)
        return line + std::string(text::no_interior_points);
    std::string message = m_options.path_name + ": " + line;
    // The frames that freeze matter more than the region, whose marks the picture shows: the two
    // do not fit one 79-column line together.
    if (evaluated().frames_freeze())
        return message + "  " + std::string(text::frames_freeze) + " at " + describe_frozen_frames(evaluated(), 1);
    const std::string of = " of " + std::to_string(points().size());
    const ControlRegion& region = staff.region;
    if (region.first == region.last)
        message += "  control point " + std::to_string(region.first + 1) + of + " (no span, no ACCELERATION)";
    else
        message += "  control points " + std::to_string(region.first + 1) + " to " + std::to_string(region.last + 1) + of;
    return message;
}

// The span whose law G shows: the region's, the arrow's while picking, the chosen waypoint's.
std::size_t PathEditor::law_point() const
{
    return std::visit(Overloaded{
                          [](const ControlChoice&) -> std::size_t { return 0; },
                          [](const RegionPick& pick) { return pick.arrow.value_or(0); },
                          [](const Staff& staff) { return staff.region.first; },
                          [](const Waypoints& waypoints) { return waypoints.editor.chosen(); },
                          [](const AskAgain& ask) { return ask.region.first; },
                      },
                      m_mode);
}

// The region boxed: the one adjusted, or its first point while the last is picked.
std::optional<ControlRegion> PathEditor::picked_region() const
{
    return std::visit(Overloaded{
                          [](const ControlChoice&) -> std::optional<ControlRegion> { return std::nullopt; },
                          [](const RegionPick& pick) -> std::optional<ControlRegion> {
                              if (!pick.first)
                                  return std::nullopt;
                              return ControlRegion{*pick.first, *pick.first};
                          },
                          [](const Staff& staff) -> std::optional<ControlRegion> {
                              return staff.region;
                          },
                          [](const Waypoints&) -> std::optional<ControlRegion> { return std::nullopt; },
                          [](const AskAgain& ask) -> std::optional<ControlRegion> {
                              return ask.region;
                          },
                      },
                      m_mode);
}

PathScreenContent PathEditor::screen_content(MoveText move) const
{
    if (const auto* waypoints = std::get_if<Waypoints>(&m_mode)) {
        const WaypointEditor& editor = waypoints->editor;
        PathScreenContent content = path_screen_content(points(), evaluated());
        content.record_strokes = false;
        content.region = ControlRegion{editor.chosen(), editor.chosen()};
        content.arrow_at = editor.chosen();
        // What O or C said, else the waypoint editor's own line.
        content.message = message(move);
        return content;
    }
    PathScreenContent content = path_screen_content(points(), evaluated());
    content.record_strokes = false;
    content.region = picked_region();
    std::visit(Overloaded{
                   [](const ControlChoice&) {},
                   [&](const RegionPick& pick) {
                       content.arrow_at = pick.arrow;
                       content.arrow_home = !pick.arrow.has_value();
                   },
                   [&](const Staff& staff) {
                       content.staff = staff.staff;
                       content.active_line = staff.line;
                   },
                   [](const Waypoints&) {},
                   [&](const AskAgain& ask) { content.staff = ask.staff; },
               },
               m_mode);
    content.message = message(move);
    return content;
}

GraphicsScreen PathEditor::view(std::optional<Vec3> goal_point, const GoalSaid& goal) const
{
    PathScreenContent content = screen_content();
    content.goal_point = goal_point;
    // A first picture says it is one (its in-betweens are not drawn); a problem matters more, and
    // a goal's feedback more than both, once the field and the last key's notice have been read;
    // the question after the staff keeps the line's start, the goal beside it.
    const bool goal_said = !goal.feedback.empty() && m_problem.empty() && m_notice.empty() && !field_open();
    if (goal_said && !std::holds_alternative<AskAgain>(m_mode))
        content.message = goal.feedback;
    else if (goal_said)
        content.message = question_with_goal(goal);
    else if (m_problem.empty() && m_picture->refining())
        content.message = refining_message();
    if (m_show_key_frames)
        content.key_frame_polylines = m_options.key_frame_polylines;
    // A pinned reference is what the curve is compared with: the ghost steps aside meanwhile.
    content.ghost = m_show_ghost && !m_picture->has_reference();
    if (m_show_tangents)
        content.tangent_scale = m_tangent_scale;
    if (m_show_law)
        content.law_span = span_of_point(*content.path, law_point());
    content.key_help = key_help(key_context());
    return m_picture->draw(content);
}

} // namespace apcs
