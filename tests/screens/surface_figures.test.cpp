#include "apcs/screens/surface_figures.h"

#include "apcs/animation/surface_fit.h"
#include "apcs/screens/figures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

using namespace apcs;

namespace {

EvaluatedPath straight_path(const Vec3& from, const Vec3& to)
{
    const ControlPoints points{{from, {}}, {to, {}}};
    return evaluate_path(points, PathSettings{});
}

// A square moved along x with straight 2-point edges: both constructions give each point its chord.
SurfaceFigureSource square_moved()
{
    const std::vector<Vec3> square{{0, 0, 0}, {0, 4, 0}, {0, 4, 4}, {0, 0, 4}};
    std::vector<Vec3> moved;
    for (const Vec3& point : square)
        moved.push_back(point + Vec3{6, 2, 1});
    const Graphic key1{{{"square", Closure::open, square}}};
    const Graphic key2{{{"square", Closure::open, moved}}};
    return {key1, key2, equalise_key_frames(key1, key2), straight_path(square.front(), moved.front()),
            straight_path(square.back(), moved.back())};
}

bool block_lit(const Bitmap& bitmap, PixelPoint centre)
{
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (!bitmap.get(centre.x + dx, centre.y + dy))
                return false;
    return true;
}

// Pixels of the drawing rows where the left half and the right half (shifted by half the width)
// differ; the divider's column is left out.
int halves_differ(const Bitmap& bitmap)
{
    const int half = bitmap.width() / 2;
    int differing = 0;
    for (int y = figure_area.top; y < figure_area.bottom; ++y)
        for (int x = 1; x < half; ++x)
            differing += bitmap.get(x, y) != bitmap.get(x + half, y) ? 1 : 0;
    return differing;
}

} // namespace

TEST_CASE("fig. 3.2.1's point A is the point Algorithm 2 added and runs through the Ferguson fit's in-betweens",
          "[figures][surface]")
{
    const SurfaceFigureSource source = thesis_surface_example(PathSettings{});
    const FergusonFigure figure = ferguson_figure(source);
    // KEY1 has 4 points and KEY2 6: Algorithm 2 adds one to each of KEY1's first two segments,
    // halfway (the thesis' A and A1); A, KEY1's point 2, goes to KEY2's point 2 (B).
    REQUIRE(figure.added_points == std::vector<Vec3>{{0, 2, 0.75}, {0, 6, 0.25}});
    REQUIRE(figure.point_a == 1);
    REQUIRE(figure.u_lines.size() == 6);
    CHECK(figure.v_lines.size() == 3);
    const FrameSequence ferguson =
        fit_key_frames(source.keys, source.first_path, source.last_path, SurfaceConstruction::ferguson);
    const FrameSequence blend = fit_key_frames(source.keys, source.first_path, source.last_path);
    REQUIRE(figure.a_inbetweens.size() == 12);
    double farthest_from_blend = 0.0;
    for (std::size_t k = 1; k <= figure.a_inbetweens.size(); ++k) {
        CAPTURE(k);
        const Vec3& shown = figure.a_inbetweens[k - 1];
        CHECK(shown == ferguson.frame(k)[1]);
        farthest_from_blend = std::max(farthest_from_blend, length(shown - blend.frame(k)[1]));
        // On the u line drawn for A: its Ferguson path (the nearest of 2001 samples).
        double nearest = 1e9;
        for (int j = 0; j <= 2000; ++j)
            nearest = std::min(nearest, length(figure.u_lines[1].point_at(j / 2000.0) - shown));
        CHECK(nearest < 0.02);
    }
    // The two constructions differ here: the figure shows the thesis', not the default.
    CHECK(farthest_from_blend > 0.5);
}

TEST_CASE("fig. 3.2.1 draws a dot at each of A's in-betweens and an x at each added point", "[figures][surface]")
{
    const SurfaceFigureSource source = thesis_surface_example(PathSettings{});
    const FergusonFigure figure = ferguson_figure(source);
    const ViewAngles angles{20, 70};
    const ViewTransform view = ferguson_figure_view(source, figure, angles);
    const GraphicsScreen screen = draw_ferguson_figure("Fig. 3.2.1", source, angles);
    for (const Vec3& point : figure.a_inbetweens)
        CHECK(block_lit(screen.bitmap, view.to_device(point).rounded()));
    // Each added point's x: its centre and its four diagonal ends, 3 pixels out.
    for (const Vec3& added : figure.added_points) {
        const PixelPoint x = view.to_device(added).rounded();
        for (const PixelPoint& lit : {x, PixelPoint{x.x - 3, x.y - 3}, PixelPoint{x.x + 3, x.y - 3},
                                      PixelPoint{x.x - 3, x.y + 3}, PixelPoint{x.x + 3, x.y + 3}})
            CHECK(screen.bitmap.get(lit.x, lit.y));
    }
    CHECK(screen.text.size() == 3);
}

TEST_CASE("the side-by-side figure shows two constructions: its halves differ exactly when they do",
          "[figures][surface]")
{
    // Edge paths with waypoints: the Ferguson surface's interior paths leave the blend's.
    const SurfaceFigureSource bent = thesis_surface_example(PathSettings{});
    CHECK(halves_differ(draw_surfaces_figure("fig. 3.2.1's pair", bent, {20, 70}).bitmap) > 100);
    // A translation with straight edges: every point runs its chord in both, so the halves agree.
    CHECK(halves_differ(draw_surfaces_figure("moved", square_moved(), {30, 40}).bitmap) == 0);
}
