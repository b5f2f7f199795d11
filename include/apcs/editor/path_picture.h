#pragma once

#include "apcs/animation/control_region.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/path_change.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/screens/curve_raster.h"
#include "apcs/editor/path_document.h"
#include "apcs/screens/path_screen.h"

#include <functional>
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

namespace apcs {

// When a picture does the work a change causes (path_change.h), and how much one step of
// Refinement::in_steps does: arc lengths measured, and the curve's drawing (CurveRaster::update's
// work: a line drawn or a segment visited is one). A step is a few milliseconds of one core.
struct PictureRefinement {
    Refinement when = Refinement::at_once;
    // Arc lengths measured a step (exact spacing), about 10 ms on two cores; a change of no more
    // segments than that is made at once.
    std::size_t segments_a_step = std::size_t{1} << 15;
    // Lines drawn (or segments passed over) a step, about 10 ms.
    std::size_t drawing_a_step = std::size_t{1} << 20;
    // Segments made a step, about 10 ms: each costs far less than its arc length.
    std::size_t segments_made_a_step = std::size_t{1} << 17;
    // Whether anyone sees the picture. Nobody sees a graded replay's (apcs grade): then the path
    // is evaluated as ever (the goals and the files read it), but the curve, the ghost, the
    // reference and the marks are never drawn — drawing them was most of each key's work — and
    // draw() shows the view with none of them.
    bool seen = true;
};

// The picture of a path being edited (a PathDocument, which it reads and never changes) for a still view:
// the path evaluated (with its arc lengths under exact spacing), its curve drawn block by block, the
// control points' pixels and their marks. Every change of the points goes through refresh(change),
// which makes again only what the change touched: the segments whose tangents the changed points
// set, the blocks of the curve that hold them, the runs of control points around them. What it keeps
// is what evaluating and drawing afresh gives, to the bit and to the pixel.
// Z (SPEC §7.2.1): ×2, ×4, ×8 (levels 1-3), then the view it started from (level 0).
inline int next_zoom_level(int level) { return level == 3 ? 0 : level + 1; }

class PathPicture {
public:
    // Evaluates the path; nothing is drawn until a view is set (the view is fitted to the path).
    // Refinement::in_steps (the terminal): a change, a view or opening does at once what the first
    // picture needs (the segments; the curve's blocks up to a step's work; the arc lengths too when
    // no more than a step's are to be measured, as after a local key) and leaves the rest to
    // refine_step(); until then refining() is true and the in-betweens are not drawn.
    // Refinement::at_once does it all at once.
    // `document` outlives the picture and keeps its address.
    // `room`: arrays for the evaluation made ahead (make_room), or none.
    PathPicture(const PathDocument& document, const PathSettings& settings, PictureRefinement refinement = {},
                EvaluatedPath room = {});

    // Turns the points after a change back into those before it: the ghost's path, drawn again
    // when the view changes (SPEC §7.2.1: the ghost stays through Z and K).
    using PointsBack = std::function<void(ControlPoints&)>;

    // The document's points changed as `change` says (called once it has changed); the ghost goes.
    void refresh(const PathChange& change);
    // The same, and the curve as it was becomes the ghost (SPEC §7.2.1), its path `back` of the
    // points; the next change replaces it.
    void refresh(const PathChange& change, PointsBack back);
    // Another view: the curve, the control points and the ghost projected again.
    void set_view(const ViewTransform& view);
    // The region whose control points' marks are boxed; the marks are made again only when it
    // changes (a path of 10^6 points scribbled over the screen has up to one mark per pixel).
    void box_region(std::optional<ControlRegion> region);

    // What Refinement::in_steps left: one step of it (a few milliseconds), or all of it. Once
    // done, everything is as at once, to the bit and to the pixel; a change made meanwhile is added
    // to what is left.
    bool refining() const;
    void refine_step();
    void refine();
    // While refining: what is left, for the message line ("drawing the curve: 12 of 245 blocks"),
    // and in a few words, to follow a question that stays on it ("measuring arc lengths").
    std::string refining_message() const;
    std::string refining_words() const;

    // The ghost is drawn dotted when the content asks, until drop_ghost or a change without one.
    void drop_ghost();
    bool has_ghost() const { return m_ghost.has_value(); }

    // Compare (C, SPEC §3.1): the curve of the points as they now are, pinned under `label` and
    // drawn dashed in this view and every later one, whatever the path becomes, until unpinned.
    void pin_reference(std::string label);
    void unpin_reference();
    bool has_reference() const { return m_reference.has_value(); }
    // Whether a reference is pinned and the curve is still the one pinned (acceleration moves only
    // the in-betweens): A is drawn, but the curve covers every dash of it.
    bool reference_under_curve() const;

    const EvaluatedPath& evaluated() const { return m_evaluated; }
    // CurveRaster::work_done of the curve's picture.
    std::size_t curve_work() const { return m_curve.work_done(); }
    const PathSettings& settings() const { return m_settings; }
    // What the picture shows: the document's revision it was made of, and its own, which every
    // change of the view, the ghost, the boxed region and every refinement step advance.
    struct Revision {
        std::uint64_t document = 0;
        std::uint64_t picture = 0;
        bool operator==(const Revision&) const = default;
    };
    Revision revision() const { return {m_document_revision, m_revision}; }
    // Only after set_view.
    const ViewTransform& view() const { return *m_view; }
    // The path screen of `content` (whose path is evaluated()) in this view, with the curve and the
    // marks as kept.
    GraphicsScreen draw(const PathScreenContent& content) const;

private:
    // The view set and its curve not yet drawn whole: a first picture's blocks are still being drawn.
    bool curve_left() const;
    void remake(const PathChange& change);
    void draw_curve();
    void draw_ghost();
    void draw_reference();
    void refine_if_quick();
    const ControlPoints& points() const { return m_document->points(); }

    const PathDocument* m_document;
    std::uint64_t m_document_revision = 0;
    std::uint64_t m_revision = 0;
    PathSettings m_settings;
    PictureRefinement m_refinement;
    EvaluatedPath m_evaluated;
    std::optional<ViewTransform> m_view;
    CurveRaster m_curve;
    std::vector<ControlPointRun> m_point_runs;
    std::optional<ControlRegion> m_region;
    std::vector<PixelMark> m_point_marks;
    std::optional<Bitmap> m_ghost;
    PointsBack m_ghost_back;
    struct Reference {
        ControlPoints points;
        std::string label;
        Bitmap pixels;
    };
    std::optional<Reference> m_reference;
};

// A waypoint edit made in `document`, or taken back, and `picture` (of the document) refreshed; the
// ghost is the path on the other side of the edit (SPEC §7.2.1).
void make_waypoint_edit(PathDocument& document, PathPicture& picture, const WaypointChange& change);
void take_back_waypoint_edit(PathDocument& document, PathPicture& picture, const WaypointChange& change);

} // namespace apcs
