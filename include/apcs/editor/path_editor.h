#pragma once

#include "apcs/animation/control_region.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/animation/waypoint_change.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/input/chart.h"
#include "apcs/input/command.h"
#include "apcs/input/key_map.h"
#include "apcs/editor/path_document.h"
#include "apcs/editor/path_picture.h"
#include "apcs/screens/path_screen.h"
#include "apcs/base/step_log.h"
#include "apcs/input/value_field.h"
#include "apcs/editor/waypoint_editor.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace apcs {

// Whether `text` fits the message line of the path screen.
bool fits_message_line(std::string_view text);

// An exercise's feedback for the message line (lesson/goal_check.h): whole ("GOAL: the curve
// passes 0.35 from (0.00, 1.00, 2.00), want within 0.10") and in a few words ("GOAL: 0.35 off,
// want within 0.10"); both empty for none.
struct GoalSaid {
    std::string_view feedback;
    std::string_view briefly;
};

// Graphics mode while one graphic point's path is shaped (thesis Ch. 4.2 steps 3–5): the choice of
// global or local control (Check_GorL_Control), picking the region with the arrow
// (Scan_Control_Point), the four-line staff (Scan_Parameters, one Scan_*_Value per line, one
// tnextpixel per key) and the question whether to adjust again (Ask_Adjusting). It owns the path
// being shaped; the session takes it back when the animator accepts it.
//
// Beyond the 1989 screen (thesis Ch. 6's future work): the tangents (T) and the law of the span (G)
// drawn over the path, a typed value on a staff line (=), the waypoint editor (W), a region of one
// control point, and undo (U) of every change since the path was opened.
class PathEditor {
public:
    // The editor's states (its chart, path_editor_chart.cpp): the leaves, and the states around
    // them whose rows the leaves share.
    enum class State {
        path_screen,    // every mode: the views (K, Z, O, C, T, G, Tab) and undo
        control_choice, // Check_GorL_Control: 8, 2 or W
        region_pick,    // Scan_Control_Point: the arrow
        region_first,   // its first point
        region_last,    // its last point
        changing_path,  // the staff and the waypoint editor: the view stays fixed
        staff,          // Scan_Parameters: a staff line takes steps
        value_field,    // "=" open on the staff line
        waypoints,      // the waypoint editor (W)
        ask_again,      // Ask_Adjusting
    };
    using EditorChart = Chart<PathEditor, State>;
    // Every row of the editor: which command does what in which state.
    static const EditorChart& chart();

    // What the editor is opened with and keeps while it shapes the path.
    struct Options {
        std::string path_name;
        PathSettings settings;
        ViewAngles view_angles;
        // Both key frames as polylines: the view keeps them in sight, and K shows them.
        std::vector<std::vector<Vec3>> key_frame_polylines;
        double staff_step = 0.05;
        // The terminal's: a key's first picture at once, the rest in refine_step() (path_picture.h).
        PictureRefinement refinement;
    };
    // The options, and what the editor hands over as it opens: the points become the document's,
    // the arrays the picture's.
    struct Setup : Options {
        ControlPoints points; // at least two
        // Arrays for the path's evaluation made ahead (make_room), or none.
        EvaluatedPath evaluation_room;
    };
    enum class Outcome { editing, accepted };

    // Initial_Graphics: evaluates the path and fixes the view for the whole adjusting, so that
    // each key's effect is seen against a still picture.
    PathEditor(Setup setup, StepLog& log);

    // A staff step or a waypoint edit adds to what the keys before it left to refine (a key held
    // down on a long path); any other command first finishes it, and so acts on the final picture.
    Outcome update(const Command& command);
    // The path screen, with an exercise's goal point marked and its feedback on the message line
    // when given (below a problem, an open field and what the last key did: SPEC §7.3).
    GraphicsScreen view(std::optional<Vec3> goal_point = std::nullopt, const GoalSaid& goal = {}) const;
    // Refinement::in_steps: whether the last keys left work (PathPicture::refining), and one step of it.
    bool refining() const { return m_picture->refining(); }
    void refine_step();
    // All of it (P writes a final picture).
    void refine();

    // The keys the editor listens with, and what a transcript calls its step: its leaf's.
    KeyContext key_context() const { return *chart().keys(leaf()); }
    std::string_view title() const { return chart().title(leaf()); }
    // The leaf of the chart the editor is in.
    State leaf() const;
    const std::string& path_name() const { return m_options.path_name; }
    const PathSettings& settings() const { return m_options.settings; }
    // The path as edited (in the waypoint editor too).
    const ControlPoints& points() const { return m_document->points(); }
    // Parallel to points(): each point's index among the path file's points, or new_point for one
    // the waypoint editor inserted (waypoint_change.h). The file's comments stay with their points.
    const std::vector<std::size_t>& point_origins() const { return m_document->origins(); }
    const PathDocument& document() const { return *m_document; }
    const EvaluatedPath& evaluated() const { return m_picture->evaluated(); }
    // The view fixed when the path was opened (fitted again when the waypoint editor is left).
    const ViewTransform& view_transform() const { return m_picture->view(); }
    // The staff's values for the region on it (while a staff line is active, and at "Adjust the
    // path again ?"); none before a region is chosen or in the waypoint editor.
    std::optional<StaffValues> region_staff() const;
    // The staff line taking keys, none off the staff.
    std::optional<StaffLine> staff_line() const;
    // The region boxed: the one on the staff or at "Adjust the path again ?", the first point
    // picked while the last is picked; none otherwise.
    std::optional<ControlRegion> region() const { return picked_region(); }
    // Advanced by every change of what the path screen shows: the editor's own, which the rows'
    // actions report (the mode, what is shown over the path, the message line), and its picture's
    // (the document's edits, the view, the ghost, the region boxed).
    std::uint64_t revision() const { return m_changes + m_picture->revision(); }
    // What the editor says on the message line; view() may show over it a goal's feedback, or
    // while the picture is refined what is left to do.
    std::string message_line() const { return message(); }
    // The accepted path could not be written: say why and ask again.
    void show_problem(const std::string& message);

private:
    // The editor's modes (lager's model: each owns what it alone needs; update visits them, so a
    // mode without a case does not compile). leaf() names them as the chart does.
    struct ControlChoice {};
    // Scan_Control_Point: the arrow waits at the top-left until moved; the region's first point
    // once picked (then the last is picked).
    struct RegionPick {
        std::optional<std::size_t> arrow;
        std::optional<std::size_t> first;
    };
    // Scan_Parameters: the region adjusted, the staff shown, its active line and that line's value
    // when it became active (Esc puts it back), and the field "=" opened on the line.
    struct Staff {
        ControlRegion region;
        StaffValues staff;
        StaffLine line = StaffLine::tension;
        double line_start_value = 0.0;
        std::optional<ValueField> field;
    };
    struct Waypoints {
        WaypointEditor editor;
    };
    // Ask_Adjusting: the region and staff just adjusted stay on the screen.
    struct AskAgain {
        ControlRegion region;
        StaffValues staff;
    };
    using Mode = std::variant<ControlChoice, RegionPick, Staff, Waypoints, AskAgain>;
    // Enter takes the line's value as shown; Esc keeps the value the line had when it became active.
    enum class LineEnding { accepted, kept };
    // Enter leaves the waypoint editor keeping its changes, Esc taking them back.
    enum class WaypointsLeft { changes_kept, changes_undone };

    Outcome take_command(const Command& command);
    // A change of what the screen shows, reported by the action that made it.
    void changed() { ++m_changes; }
    // A mode entered: the screen shows another step (or the staff another region).
    void enter(Mode mode);
    // `change` done, and a change counted when the message line says another thing. Its words come
    // from a dozen places in order (a problem, the field, what the last key did, the mode's
    // question, T's numbers, the move a staff key made): only its text tells.
    template <typename Change>
    void saying(Change change);
    // The rows' actions and guards (path_editor_chart.cpp makes them the chart's rows).
    static EditorChart make_chart();
    static std::vector<EditorChart::Row> screen_rows();
    static std::vector<EditorChart::Row> region_rows();
    static std::vector<EditorChart::Row> staff_rows();
    static std::vector<EditorChart::Row> waypoint_and_question_rows();
    void move_arrow(const command::ArrowMove& move);
    void pick_last_point();
    bool staff_line_is_last() const;
    void end_staff_line(LineEnding ending);
    void set_typed_value();
    void leave_waypoints(WaypointsLeft left);
    WaypointEditor& waypoint_editor() { return std::get<Waypoints>(m_mode).editor; }
    void toggle_key_frames();
    void toggle_ghost();
    void choose_tangent_point(const command::ChoosePoint& choose);
    void say_nothing_to_undo();
    bool last_edit_is_staff() const;
    Staff start_staff(ControlRegion region);
    Waypoints open_waypoints();
    void set_staff_value(Staff& staff, double value);
    // m_moved from m_move_unmeasured once the picture is refined: when the message is shown, not
    // at every key (a replay of 10^6 staff keys shows a few).
    void measure_move_when_refined() const;
    // Whether the message measures a staff key's move, or leaves it for when it is shown.
    enum class MoveText { measured, left_unmeasured };
    void undo();
    void undone(const StaffEdit& change);
    void undone(const WaypointChange& change);
    // The view filled with the path (and the key frames while K shows them), then zoomed.
    void fit_view();
    void show_view();
    bool zoom();
    void pin_or_unpin_reference();
    std::optional<ControlRegion> picked_region() const;
    std::size_t law_point() const;
    std::string message(MoveText move = MoveText::measured) const;
    std::string with_reference_told(std::string numbers) const;
    // While the picture is refined: what is left, or the 8/2 question followed by it.
    std::string refining_message() const;
    // A staff line's "=" field is open: what is typed there is on the message line.
    bool field_open() const;
    std::string staff_message(const Staff& staff) const;
    std::string with_move(const std::string& shown, const Staff& staff, MoveText move) const;
    PathScreenContent screen_content(MoveText move = MoveText::measured) const;

    Options m_options;
    StepLog& m_log;
    // The path (its points, origins and undo history) and its picture: evaluated and drawn in the
    // view fixed for the adjusting, kept between keys, every change refreshing only what it
    // touched. Both editors change them in place; held apart so that their addresses outlive a
    // move of the editor.
    std::unique_ptr<PathDocument> m_document;
    std::unique_ptr<PathPicture> m_picture;
    // SPEC §7.2.1: the view filled with what is shown, fixed while the staff or the waypoint editor
    // changes the path (refitted when they are left, and by K); Z magnifies it 2^m_zoom_level
    // times (0 to 3) about m_zoom_about (the region's middle, or the sample halfway along the curve).
    std::optional<ViewTransform> m_fitted_view;
    int m_zoom_level = 0;
    std::optional<Vec3> m_zoom_about;
    // T: arrows at a fixed scale (fitted with the view), the numbers of one control point.
    double m_tangent_scale = 0.0;
    Mode m_mode;
    // The command taken accepted the path (N at "Adjust the path again ?").
    bool m_accepted = false;
    // What is shown over every mode (K, T, G and the point T numbers) and said on the message line:
    // a problem until it is dealt with, and what the last key did, said once (an undo, a clamped
    // value).
    bool m_show_key_frames = false;
    // O: the ghost of the curve before the last staff key or waypoint edit (PathPicture keeps it).
    bool m_show_ghost = true;
    bool m_show_tangents = false;
    std::size_t m_tangent_point = 1;
    bool m_show_law = false;
    std::string m_problem;
    std::string m_notice;
    // After a staff key: how far it moved the curve ("moved up to 0.024 = 1 px").
    mutable std::string m_moved;
    // A staff key whose move is measured once its picture is refined in steps: its edit in the
    // document's history. The message line says what is refined meanwhile, and neither the
    // segments before the key (made again from the points and the edit's runs: 2 ms for a global
    // key's 4096 on 10^6 points) nor the search (about 8 ms) holds up the first picture. Every
    // command drops it, so the points are still those the key left.
    mutable std::optional<std::size_t> m_move_unmeasured;
    // The editor's own changes (revision()).
    std::uint64_t m_changes = 0;
};

} // namespace apcs
