#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/animation/waypoint_change.h"
#include "apcs/geometry/bounding_box.h"
#include "apcs/input/command.h"
#include "apcs/editor/path_document.h"
#include "apcs/editor/path_picture.h"

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
        ViewTransform view; // the path screen's view: fixed while editing
        double step = 1.0;  // world units of one step (waypoint_step)
    };
    // Edits `document` in place (its picture, `picture`, in setup.view, shows each edit as it is
    // next read, the curve before it dotted: SPEC §7.2.1); both outlive the editor. Chooses the
    // first control point. Its edits join the document's history as they are made; Esc takes them
    // back.
    WaypointEditor(PathDocument& document, PathPicture& picture, Setup setup);

    // The keys of the editor, each a row of the path editor's chart (path_editor_chart.cpp); Enter
    // keeps the changes and needs nothing of the editor.
    // Tab, Shift-Tab, ] and [: another point chosen, `by` points on.
    void choose(int by);
    // The moves: the chosen point shifted by steps (the key frames' points stay, said why).
    void move(const command::MovePoint& move);
    // I: a point inserted halfway to the next after the chosen one, chosen.
    void insert();
    // D: the chosen point deleted (not a key frame's).
    void remove();
    // U: the editor's last change taken back.
    void undo();
    // Z: ×2, ×4, ×8 about the chosen point, then the view the editor opened with.
    void zoom();
    // Esc: every change since the editor opened taken back, newest first.
    void discard();

    const ControlPoints& points() const { return m_document->points(); }
    const std::vector<std::size_t>& origins() const { return m_document->origins(); }
    std::size_t chosen() const { return m_chosen; }
    // The edits made since the editor opened (U takes back the last of them).
    std::size_t change_count() const { return m_document->edit_count() - m_first_edit; }
    // "control point 2 of 5  depth +0.30", or the problem of the last key.
    std::string message() const;

private:
    // `edit` done, the chosen point boxed, what the last key said gone first.
    template <typename Edit>
    void taking(Edit edit);
    void insert_point();
    void delete_point();
    void move_point(const command::MovePoint& move);
    void undo_last();
    void zoom_view();
    void discard_changes();
    // The last edit taken back, the ghost the path with it.
    void revert_last();
    // The key frames' points never move: true (and the message says why) for them.
    bool is_key_frame_point(std::size_t index);

    PathDocument* m_document;
    PathPicture* m_picture;
    Setup m_setup;
    std::size_t m_first_edit = 0;
    std::size_t m_chosen = 0;
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
