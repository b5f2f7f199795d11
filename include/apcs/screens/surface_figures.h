#pragma once

#include "apcs/animation/add_points.h"
#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/hermite.h"
#include "apcs/animation/motion_path.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/graphics_screen.h"

#include <string>
#include <vector>

namespace apcs {

// A key-frame pair ready for surface fitting: the keys as read (so that the points Algorithm 2
// added can be told apart), the keys equalised, and the evaluated paths of the first and the last
// graphic point (the edge paths).
struct SurfaceFigureSource {
    Graphic key1;
    Graphic key2;
    EqualisedKeys keys;
    EvaluatedPath first_path;
    EvaluatedPath last_path;
};

// The pair fig. 3.2.1 is drawn from, as the thesis describes its figure: KEY1 of four points and
// KEY2 of six, both open, so that Algorithm 2 adds two points (the thesis' A and A1) to KEY1; KEY1
// lies low and KEY2 high in the y-z plane, and each edge path bends out through one waypoint.
SurfaceFigureSource thesis_surface_example(const PathSettings& settings);

// What fig. 3.2.1 shows, in world units: the thesis' Ferguson surface (SPEC §5.3.1) of a pair.
struct FergusonFigure {
    // Points of the equalised keys that the keys as read do not have (the thesis marks them `x`).
    std::vector<Vec3> added_points;
    // The surface's u lines: every graphic point's path on the zero-twist surface, the first and
    // the last point's included (their own edges see only the edge paths' end tangents).
    std::vector<HermiteSegment> u_lines;
    // Its v lines: the surface across the graphic at u = 1/4, 1/2, 3/4, drawn as the keys are.
    std::vector<std::vector<Vec3>> v_lines;
    // Point A: the first interior point with an added point in either key (the thesis' A moves to
    // B), else the middle point; and A in the in-betweens of `apcs fit --surface ferguson`.
    std::size_t point_a = 0;
    std::vector<Vec3> a_inbetweens;
};

// The Ferguson surface of `source` (ferguson_point_paths from the edge paths' end tangents) and
// point A's in-betweens (fit_key_frames with SurfaceConstruction::ferguson).
FergusonFigure ferguson_figure(const SurfaceFigureSource& source);

// The view fig. 3.2.1 is drawn in: the keys, the edge paths and the surface in sight.
ViewTransform ferguson_figure_view(const SurfaceFigureSource& source, const FergusonFigure& figure,
                                   ViewAngles angles);

// Fig. 3.2.1 redrawn (thesis Ch. 3.2): KEY1 and KEY2 solid with their added points marked `x`, the
// edge paths dashed, the surface's u and v lines dotted, point A's path solid with its in-betweens
// as dots; the corners numbered 1 … 4 as the thesis names them (1, 2: the first point in KEY1 and
// KEY2; 3, 4: the last point's), A lettered in KEY1 and B in KEY2; a legend names each stroke.
GraphicsScreen draw_ferguson_figure(const std::string& title, const SurfaceFigureSource& source, ViewAngles angles);

// All frames of both constructions side by side at one scale: `--surface blend` (SPEC §5.3) in the
// left half, `--surface ferguson` (§5.3.1) in the right, each captioned above, KEY1 and KEY2 solid
// and the in-betweens dotted as in draw_frames_figure.
GraphicsScreen draw_surfaces_figure(const std::string& title, const SurfaceFigureSource& source, ViewAngles angles);

} // namespace apcs
