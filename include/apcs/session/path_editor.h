#pragma once

#include "apcs/animation/control_region.h"
#include "apcs/animation/graphic.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/animation/waypoint_change.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/session/command.h"
#include "apcs/session/key_map.h"
#include "apcs/session/session_log.h"
#include "apcs/session/session_phase.h"

#include <optional>
#include <string>
#include <vector>

namespace apcs {

// Graphics mode while one graphic point's path is shaped (thesis Ch. 4.2 steps 3–5): the choice of
// global or local control (Check_GorL_Control), picking the region with the arrow
// (Scan_Control_Point), the four-line staff (Scan_Parameters, one Scan_*_Value per line, one
// tnextpixel per key) and the question whether to adjust again (Ask_Adjusting). It owns the path
// being shaped; the session takes it back when the animator accepts it.
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

    SessionPhase phase() const { return m_phase; }
    KeyContext key_context() const;
    const std::string& path_name() const { return m_setup.path_name; }
    const ControlPoints& points() const { return m_setup.points; }
    // Parallel to points(): each point's index among the path file's points, or new_point for one
    // the waypoint editor inserted (waypoint_change.h). The file's comments stay with their points.
    const std::vector<std::size_t>& point_origins() const { return m_origins; }
    const EvaluatedPath& evaluated() const { return m_evaluated; }
    // The accepted path could not be written: say why and ask again.
    void show_problem(const std::string& message);

private:
    void check_global_or_local_control(const Command& command);
    void scan_control_point(const Command& command);
    void scan_parameters(const Command& command);
    Outcome ask_adjusting(const Command& command);
    void start_staff(ControlRegion region);
    void set_staff_value(double value);
    std::string message() const;
    std::string staff_message() const;

    Setup m_setup;
    std::vector<std::size_t> m_origins;
    SessionLog& m_log;
    EvaluatedPath m_evaluated;
    ViewTransform m_view;
    SessionPhase m_phase = SessionPhase::choose_control;
    bool m_show_key_frames = false;
    std::string m_problem;

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
};

} // namespace apcs
