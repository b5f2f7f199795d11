#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/animation/waypoint_change.h"
#include "apcs/geometry/bounding_box.h"
#include "apcs/session/command.h"
#include "apcs/session/path_picture.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace apcs {

// The waypoint editor (W at the 8/2 choice): control points inserted, deleted and moved in the
// screen's plane, keyboard only, against a still view. The first and the last control point are
// the key frames' points and stay. Every edit is one reversible WaypointChange, so that U and Esc
// take edits back exactly and the path editor can undo them later one by one.
class WaypointEditor {
public:
    struct Setup {
        ControlPoints points;             // at least two
        std::vector<std::size_t> origins; // parallel to points (waypoint_change.h)
        PathSettings settings;            // to evaluate the path as it changes
        ViewTransform view;               // the path screen's view: fixed while editing
        double step = 1.0;                // world units of one step (waypoint_step)
    };
    enum class Outcome { editing, kept, discarded };

    // Chooses the first control point; evaluates and draws the path.
    explicit WaypointEditor(Setup setup);
    // The same with the path's picture as the path editor keeps it (of setup.points in setup.view):
    // the editor refreshes it at each edit and hands it back when it is left.
    WaypointEditor(Setup setup, PathPicture picture);

    Outcome update(const Command& command);

    const ControlPoints& points() const { return m_setup.points; }
    const std::vector<std::size_t>& origins() const { return m_setup.origins; }
    const EvaluatedPath& evaluated() const { return m_picture.evaluated(); }
    const PathPicture& picture() const { return m_picture; }
    // What the last edits left to refine (PathPicture::refine_step, refine).
    void refine_step() { m_picture.refine_step(m_setup.points); }
    void refine() { m_picture.refine(m_setup.points); }
    // Once left: the points with their origins and their picture, as kept or as they were.
    struct Path {
        ControlPoints points;
        std::vector<std::size_t> origins;
        PathPicture picture;
    };
    Path hand_back() &&;
    std::size_t chosen() const { return m_chosen; }
    // The changes applied since the editor opened, oldest first.
    const std::vector<WaypointChange>& changes() const { return m_changes; }
    // "control point 2 of 5  depth +0.30", or the problem of the last key.
    std::string message() const;

private:
    Outcome take_command(const Command& command);
    void insert_point();
    void delete_point();
    void move_point(const command::MovePoint& move);
    void undo();
    // Z: ×2, ×4, ×8 about the chosen point, then the view the editor opened with.
    void zoom();
    // Esc: every change since the editor opened taken back, newest first.
    Outcome discard();
    void apply(const WaypointChange& change);
    // The key frames' points never move: true (and the message says why) for them.
    bool is_key_frame_point(std::size_t index);

    Setup m_setup;
    PathPicture m_picture;
    std::size_t m_chosen = 0;
    std::vector<WaypointChange> m_changes;
    std::string m_problem;
    std::string m_notice; // what the last key did, when it says more than the status
    int m_zoom_level = 0;
};

// One step of the editor: 1 % of the diagonal of the bounding box of what the view shows.
double waypoint_step(const BoundingBox& shown);

// The point on the curve of `segments` halfway by arc length from control point `from` to the
// next one (from < segments.size()).
Vec3 halfway_along(std::span<const HermiteSegment> segments, std::size_t from);

} // namespace apcs
