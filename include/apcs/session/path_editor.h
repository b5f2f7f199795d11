#pragma once

#include "apcs/animation/control_region.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/animation/waypoint_change.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/session/command.h"
#include "apcs/session/key_map.h"
#include "apcs/session/path_screen.h"
#include "apcs/session/session_log.h"
#include "apcs/session/session_phase.h"
#include "apcs/session/value_field.h"
#include "apcs/session/waypoint_editor.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace apcs {

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
    struct Setup {
        std::string path_name;
        ControlPoints points; // at least two
        PathSettings settings;
        ViewAngles view_angles;
        // Both key frames as polylines: the view keeps them in sight, and K shows them.
        std::vector<std::vector<Vec3>> key_frame_polylines;
        double staff_step = 0.05;
    };
    enum class Outcome { editing, accepted };

    // Initial_Graphics: evaluates the path and fixes the view for the whole adjusting, so that
    // each key's effect is seen against a still picture.
    PathEditor(Setup setup, SessionLog& log);

    Outcome update(const Command& command);
    GraphicsScreen view() const;

    SessionPhase phase() const;
    KeyContext key_context() const;
    const std::string& path_name() const { return m_setup.path_name; }
    const ControlPoints& points() const { return m_setup.points; }
    // Parallel to points(): each point's index among the path file's points, or new_point for one
    // the waypoint editor inserted (waypoint_change.h). The file's comments stay with their points.
    const std::vector<std::size_t>& point_origins() const { return m_origins; }
    const EvaluatedPath& evaluated() const { return m_evaluated; }
    // The view fixed when the path was opened (fitted again when the waypoint editor is left).
    const ViewTransform& view_transform() const { return m_view; }
    // The accepted path could not be written: say why and ask again.
    void show_problem(const std::string& message);

private:
    // A key on the staff: the staff, the region and the line as they were, and the region's
    // points' values before it.
    struct StaffChange {
        ControlRegion region;
        StaffLine line = StaffLine::tension;
        StaffValues staff;
        double line_start_value = 0.0;
        std::vector<StaffRun> points_before;
    };
    using Change = std::variant<StaffChange, WaypointChange>;

    Outcome take_command(const Command& command);
    bool update_views(const Command& command);
    void check_global_or_local_control(const Command& command);
    void scan_control_point(const Command& command);
    void scan_parameters(const Command& command);
    void accept_staff_line(bool keep);
    Outcome ask_adjusting(const Command& command);
    void start_staff(ControlRegion region);
    void set_staff_value(double value);
    void reevaluate_region(ControlRegion region, bool shape_changed);
    void update_value_field(const Command& command);
    void open_waypoints();
    void update_waypoints(const Command& command);
    void undo();
    void undo_change(const StaffChange& change);
    void undo_change(const WaypointChange& change);
    void fit_view();
    void evaluate_whole_path();
    void mark_control_points();
    void refresh_point_marks();
    std::optional<PickedRegion> picked_region() const;
    bool single_point_region() const { return m_region.first == m_region.last; }
    std::size_t law_point() const;
    std::string message() const;
    std::string staff_message() const;
    PathScreenContent screen_content() const;

    Setup m_setup;
    std::vector<std::size_t> m_origins;
    SessionLog& m_log;
    EvaluatedPath m_evaluated;
    ViewTransform m_view;
    // The picture of the path kept between keys: only what a key changed is projected again.
    CurveRaster m_curve_raster;
    std::vector<ControlPointRun> m_point_runs;
    std::vector<PixelMark> m_point_marks;
    std::optional<std::optional<PickedRegion>> m_marks_region; // the region m_point_marks show
    // T: arrows at a fixed scale (fitted with the view), the numbers of one control point.
    double m_tangent_scale;
    SessionPhase m_phase = SessionPhase::choose_control;
    bool m_show_key_frames = false;
    std::string m_problem;
    // What the last key did, said once on the message line (an undo, a clamped value).
    std::string m_notice;

    // Scan_Control_Point: the arrow waits at the top-left until moved; the region's first point
    // once picked.
    std::optional<std::size_t> m_arrow;
    std::size_t m_region_first = 0;

    // Scan_Parameters: the region adjusted, the staff shown, its active line and that line's value
    // when it became active (Esc puts it back).
    ControlRegion m_region;
    StaffValues m_staff;
    StaffLine m_line = StaffLine::tension;
    double m_line_start_value = 0.0;
    std::optional<ValueField> m_field;

    bool m_show_tangents = false;
    std::size_t m_tangent_point = 1;
    bool m_show_law = false;

    std::optional<WaypointEditor> m_waypoints;
    // Every change since the path was opened, oldest first: U takes back the last.
    std::vector<Change> m_history;
};

} // namespace apcs
