#pragma once

#include "apcs/animation/control_region.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/path_change.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/screens/curve_raster.h"
#include "apcs/editor/path_document.h"
#include "apcs/screens/path_screen.h"

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

// Z (SPEC §7.2.1): ×2, ×4, ×8 (levels 1-3), then the view it started from (level 0).
inline int next_zoom_level(int level) { return level == 3 ? 0 : level + 1; }

// The picture of a path's control points for a still view, told each change of them: the path
// evaluated (with its arc lengths under exact spacing), its curve drawn block by block, the control
// points' pixels and their marks. refresh(change) makes again only what the change touched: the
// segments whose tangents the changed points set, the blocks of the curve that hold them, the runs
// of control points around them. What it keeps is what evaluating and drawing afresh gives, to the
// bit and to the pixel. A PathPicture tells it its document's changes.
class PointsPicture {
public:
    // Evaluates the path; nothing is drawn until a view is set (the view is fitted to the path).
    // Refinement::in_steps (the terminal): a change, a view or opening does at once what the first
    // picture needs (the segments; the curve's blocks up to a step's work; the arc lengths too when
    // no more than a step's are to be measured, as after a local key) and leaves the rest to
    // refine_step(); until then refining() is true and the in-betweens are not drawn.
    // Refinement::at_once does it all at once.
    // `points` outlive the picture and keep their address.
    // `room`: arrays for the evaluation made ahead (make_room), or none.
    PointsPicture(const ControlPoints& points, const PathSettings& settings, PictureRefinement refinement = {},
                  EvaluatedPath room = {});

    // The points changed as `change` says (called once they have changed): the curve as it was
    // becomes the ghost (SPEC §7.2.1), its path `back` of the points (drawn again when the view
    // changes: the ghost stays through Z and K); the next change replaces it.
    void refresh(const PathChange& change, PointsBack back);
    // The points changed in ways not told: everything made again, no ghost.
    void remake_whole();
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
    // Advanced by every change of what the picture shows: of the points, the view, the ghost, the
    // boxed region, the reference, and by every refinement step.
    std::uint64_t revision() const { return m_revision; }
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
    const ControlPoints& points() const { return *m_points; }

    const ControlPoints* m_points;
    // The points' count the picture was made for (remake_whole's change).
    std::size_t m_point_count = 0;
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

// The picture of a path being edited (a PathDocument): a PointsPicture reached only through
// current(), which first takes the document's changes since the picture last looked (their ghost is
// the curve before them). Whoever changes the document tells the picture nothing; whatever reads
// or draws it sees the document as it is: a stale picture cannot be drawn.
class PathPicture {
public:
    // `document` outlives the picture and keeps its address; the picture is its one reader of
    // changes (PathDocument::take_changes).
    PathPicture(PathDocument& document, const PathSettings& settings, PictureRefinement refinement = {},
                EvaluatedPath room = {});
    // A copy would be a second reader of the document's changes; a move hands the one reading on.
    PathPicture(const PathPicture&) = delete;
    PathPicture& operator=(const PathPicture&) = delete;
    PathPicture(PathPicture&&) = default;
    PathPicture& operator=(PathPicture&&) = default;

    // The document's changes taken now: a series of changes far apart, each taken as it is made,
    // stays a few segments each, where taken together they cover the span between them.
    void catch_up() { current(); }

    void set_view(const ViewTransform& view) { current().set_view(view); }
    void box_region(std::optional<ControlRegion> region) { current().box_region(region); }
    bool refining() { return current().refining(); }
    void refine_step() { current().refine_step(); }
    void refine() { current().refine(); }
    std::string refining_message() { return current().refining_message(); }
    std::string refining_words() { return current().refining_words(); }
    void drop_ghost() { current().drop_ghost(); }
    bool has_ghost() { return current().has_ghost(); }
    void pin_reference(std::string label) { current().pin_reference(std::move(label)); }
    void unpin_reference() { current().unpin_reference(); }
    bool has_reference() { return current().has_reference(); }
    bool reference_under_curve() { return current().reference_under_curve(); }
    const EvaluatedPath& evaluated() { return current().evaluated(); }
    std::size_t curve_work() { return current().curve_work(); }
    const PathSettings& settings() const { return m_picture.settings(); }
    // Advanced by every change of what the picture shows, its document's included.
    std::uint64_t revision() { return current().revision(); }
    const ViewTransform& view() { return current().view(); }
    GraphicsScreen draw(const PathScreenContent& content) { return current().draw(content); }

private:
    // The picture of the document as it is now.
    PointsPicture& current();

    PathDocument* m_document;
    std::uint64_t m_document_revision = 0;
    PointsPicture m_picture;
};

} // namespace apcs
