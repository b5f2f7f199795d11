#include "apcs/editor/path_editor.h"

// The editor's chart: every command the key map lets through in each of its leaves is a row here
// or a written ignore (tests/input/charts.test.cpp walks them; the chart prints itself
// to tests/golden/session_chart.txt, below the session's).
namespace apcs {

namespace {

using State = PathEditor::State;
using Row = PathEditor::EditorChart::Row;
// The rows' lambdas: an action takes (E&, C), a guard (const E&, C).
using E = PathEditor;
using C = const Command&;

} // namespace

const PathEditor::EditorChart& PathEditor::chart() { return EditorChart::once<&make_chart>(); }

PathEditor::EditorChart PathEditor::make_chart()
{
    std::vector<EditorChart::StateInfo> states = {
        {State::path_screen, "path_screen", std::nullopt},
        {State::control_choice, "control_choice", State::path_screen, KeyContext::control_choice,
         "step 3: global or local control"},
        {State::region_pick, "region_pick", State::path_screen, KeyContext::region_pick},
        {State::region_first, "region_first", State::region_pick, {}, "step 3: first control point of the region"},
        {State::region_last, "region_last", State::region_pick, {}, "step 3: last control point of the region"},
        {State::changing_path, "changing_path", State::path_screen, {}, {}, "the view fitted to the path as it now stands",
         [](E& e) { e.fit_view(); }},
        {State::staff, "staff", State::changing_path, KeyContext::staff, "step 4: four-line staff"},
        // The field is a line of the staff: a transcript names the staff.
        {State::value_field, "value_field", State::changing_path, KeyContext::value_field, "step 4: four-line staff"},
        {State::waypoints, "waypoints", State::changing_path, KeyContext::waypoints, "step 3: waypoint editor"},
        {State::ask_again, "ask_again", State::path_screen, KeyContext::adjust_again, "step 5: adjust again"},
    };
    std::vector<Row> rows;
    for (std::vector<Row> (*part)() : {screen_rows, region_rows, staff_rows, waypoint_and_question_rows}) {
        std::vector<Row> more = part();
        rows.insert(rows.end(), more.begin(), more.end());
    }
    return EditorChart(std::move(states), std::move(rows));
}

// What is shown, never the path, in every mode (the waypoint editor's own rows first), and undo.
std::vector<PathEditor::EditorChart::Row> PathEditor::screen_rows()
{
    return {
        {State::path_screen, on<command::ToggleKeyFrames>, {}, nullptr, "key frames shown or hidden, the view fitted",
         [](E& e, C) { e.toggle_key_frames(); }},
        {State::path_screen, on<command::Zoom>, {}, nullptr, "the view zoomed x2, x4, x8, then fitted",
         [](E& e, C) { e.zoom(); }},
        {State::path_screen, on<command::ToggleGhost>, {}, nullptr, "the ghost shown or hidden, said",
         [](E& e, C) { e.toggle_ghost(); }},
        {State::path_screen, on<command::PinReference>, {}, nullptr, "the curve pinned as A, or A unpinned",
         [](E& e, C) { e.pin_or_unpin_reference(); }},
        {State::path_screen, on<command::ToggleTangents>, {}, nullptr, "the tangents shown or hidden",
         [](E& e, C) {
             e.m_show_tangents = !e.m_show_tangents;
             e.changed();
         }},
        {State::path_screen, on<command::ToggleLawGraph>, {}, nullptr, "the law graph shown or hidden",
         [](E& e, C) {
             e.m_show_law = !e.m_show_law;
             e.changed();
         }},
        {State::path_screen, on<command::ChoosePoint>, {}, nullptr, "T's numbers at another control point",
         [](E& e, C c) { e.choose_tangent_point(std::get<command::ChoosePoint>(c)); }},
        {State::path_screen, on<command::Undo>, "nothing to undo",
         [](const E& e, C) { return e.m_document->edit_count() == 0; }, "said: nothing to undo",
         [](E& e, C) { e.say_nothing_to_undo(); }},
        {State::path_screen, on<command::Undo>, "the last change a staff value",
         [](const E& e, C) { return e.last_edit_is_staff(); }, "the staff value back, on its line",
         [](E& e, C) { e.undo(); }, State::staff},
        {State::path_screen, on<command::Undo>, {}, nullptr, "the waypoint edit taken back, the view fitted",
         [](E& e, C) { e.undo(); }, State::control_choice},
    };
}

// Check_GorL_Control and Scan_Control_Point.
std::vector<PathEditor::EditorChart::Row> PathEditor::region_rows()
{
    return {
        {State::control_choice, on<command::ChooseGlobal>, {}, nullptr, "global control: the staff on the whole path",
         [](E& e, C) {
             e.m_log.log("global control");
             e.enter(e.start_staff(ControlRegion::whole(e.points())));
         },
         State::staff},
        {State::control_choice, on<command::ChooseLocal>, {}, nullptr, "the arrow waits at the top-left",
         [](E& e, C) { e.enter(RegionPick{}); }, State::region_first},
        {State::control_choice, on<command::OpenWaypoints>, {}, nullptr, "the waypoint editor opened",
         [](E& e, C) { e.enter(e.open_waypoints()); }, State::waypoints},

        {State::region_pick, on<command::ArrowMove>, {}, nullptr, "the arrow moved (its first move: to point 1)",
         [](E& e, C c) { e.move_arrow(std::get<command::ArrowMove>(c)); }},
        {State::region_first, on<command::Back>, {}, nullptr, "one step back",
         [](E& e, C) {
             e.m_problem.clear();
             e.enter(ControlChoice{});
         },
         State::control_choice},
        {State::region_first, on<command::Accept>, "the arrow not moved yet",
         [](const E& e, C) { return !std::get<RegionPick>(e.m_mode).arrow; }, "Enter points at nothing"},
        {State::region_first, on<command::Accept>, {}, nullptr, "the arrow's point is the first",
         [](E& e, C) {
             e.m_problem.clear();
             const std::optional<std::size_t> arrow = std::get<RegionPick>(e.m_mode).arrow;
             e.enter(RegionPick{arrow, arrow});
         },
         State::region_last},
        {State::region_last, on<command::Back>, {}, nullptr, "the first point picked again",
         [](E& e, C) {
             e.m_problem.clear();
             e.enter(RegionPick{std::get<RegionPick>(e.m_mode).arrow, std::nullopt});
         },
         State::region_first},
        {State::region_last, on<command::Accept>, "the arrow before the first point",
         [](const E& e, C) {
             const RegionPick& pick = std::get<RegionPick>(e.m_mode);
             return *pick.arrow < *pick.first;
         },
         "said: the last must come after the first",
         [](E& e, C) {
             e.m_problem = "The last control point must come after the first (point " +
                           std::to_string(*std::get<RegionPick>(e.m_mode).first + 1) + ")";
         }},
        {State::region_last, on<command::Accept>, {}, nullptr, "the region logged, the staff on it",
         [](E& e, C) { e.pick_last_point(); }, State::staff},
    };
}

// Scan_Parameters: the staff's lines, and the "=" field on one.
std::vector<PathEditor::EditorChart::Row> PathEditor::staff_rows()
{
    return {
        {State::staff, on<command::StaffStep>, {}, nullptr, "the line's value stepped (one tnextpixel)",
         [](E& e, C c) {
             Staff& staff = std::get<Staff>(e.m_mode);
             e.set_staff_value(staff, staff.staff[staff.line] +
                                          std::get<command::StaffStep>(c).steps * e.m_options.staff_step);
         }},
        {State::staff, on<command::OpenValueField>, {}, nullptr, "the field opened on the message line",
         [](E& e, C) {
             std::get<Staff>(e.m_mode).field.emplace();
             e.changed();
         }, State::value_field},
        {State::staff, on<command::Accept>, "the last line", [](const E& e, C) { return e.staff_line_is_last(); },
         "the line's value logged", [](E& e, C) { e.end_staff_line(LineEnding::accepted); }, State::ask_again},
        {State::staff, on<command::Accept>, {}, nullptr, "the line's value logged, the next line",
         [](E& e, C) { e.end_staff_line(LineEnding::accepted); }, State::staff},
        {State::staff, on<command::Keep>, "the last line", [](const E& e, C) { return e.staff_line_is_last(); },
         "the line's value put back, logged (kept)", [](E& e, C) { e.end_staff_line(LineEnding::kept); },
         State::ask_again},
        {State::staff, on<command::Keep>, {}, nullptr, "the line's value put back, logged (kept), the next line",
         [](E& e, C) { e.end_staff_line(LineEnding::kept); }, State::staff},

        {State::value_field, on<command::TypeCharacter>, {}, nullptr, "typed into the field ('=' first: ignored)",
         [](E& e, C c) { std::get<Staff>(e.m_mode).field->type(std::get<command::TypeCharacter>(c).character); }},
        {State::value_field, on<command::EraseCharacter>, {}, nullptr, "the field's last character erased",
         [](E& e, C) { std::get<Staff>(e.m_mode).field->erase(); }},
        {State::value_field, on<command::SubmitLine>, "the field holds a number",
         [](const E& e, C) { return std::get<Staff>(e.m_mode).field->holds_number(); },
         "the line set to it (clamped to the staff: said), logged", [](E& e, C) { e.set_typed_value(); },
         State::staff},
        {State::value_field, on<command::SubmitLine>, {}, nullptr, "said why it is no number, the field emptied",
         [](E& e, C) { std::get<Staff>(e.m_mode).field->submit(); }},
        {State::value_field, on<command::ClearLine>, {}, nullptr, "the field closed, the value as it was",
         [](E& e, C) {
             std::get<Staff>(e.m_mode).field.reset();
             e.changed();
         }, State::staff},
        // The key map sends U there as typed text; the chart keeps undo from under an open field.
        {State::value_field, on<command::Undo>, {}, nullptr, "the field takes text keys only"},
    };
}

// The waypoint editor and Ask_Adjusting.
std::vector<PathEditor::EditorChart::Row> PathEditor::waypoint_and_question_rows()
{
    return {
        {State::waypoints, on<command::ChoosePoint>, {}, nullptr, "another point chosen",
         [](E& e, C c) { e.waypoint_editor().choose(std::get<command::ChoosePoint>(c).by); }},
        {State::waypoints, on<command::MovePoint>, {}, nullptr, "the chosen point moved",
         [](E& e, C c) { e.waypoint_editor().move(std::get<command::MovePoint>(c)); }},
        {State::waypoints, on<command::InsertPoint>, {}, nullptr, "a point inserted after the chosen one",
         [](E& e, C) { e.waypoint_editor().insert(); }},
        {State::waypoints, on<command::DeletePoint>, {}, nullptr, "the chosen point deleted (or why not)",
         [](E& e, C) { e.waypoint_editor().remove(); }},
        {State::waypoints, on<command::Undo>, {}, nullptr, "the editor's last change taken back",
         [](E& e, C) { e.waypoint_editor().undo(); }},
        {State::waypoints, on<command::Zoom>, {}, nullptr, "zoomed about the chosen point",
         [](E& e, C) { e.waypoint_editor().zoom(); }},
        {State::waypoints, on<command::ToggleKeyFrames>, {}, nullptr, "key frames shown or hidden, the view kept",
         [](E& e, C) {
             e.m_show_key_frames = !e.m_show_key_frames;
             e.changed();
         }},
        {State::waypoints, on<command::Accept>, {}, nullptr, "the changes kept, said and logged",
         [](E& e, C) { e.leave_waypoints(WaypointsLeft::changes_kept); }, State::control_choice},
        {State::waypoints, on<command::Back>, {}, nullptr, "the changes undone, said and logged",
         [](E& e, C) { e.leave_waypoints(WaypointsLeft::changes_undone); }, State::control_choice},

        {State::ask_again, on<command::Yes>, {}, nullptr, "the ghost dropped",
         [](E& e, C) {
             e.m_picture->drop_ghost();
             e.enter(ControlChoice{});
         },
         State::control_choice},
        {State::ask_again, on<command::No>, {}, nullptr, "the path accepted: the session takes it",
         [](E& e, C) { e.m_accepted = true; }},
    };
}

} // namespace apcs
