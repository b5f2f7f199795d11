// The path screen's kept curve (CurveRaster: block by block, runs along a row lit a byte at a time,
// lines inside the clip lit without a painter) lights the pixels a painter's solid lines through
// the samples light (draw_world_curve), each sample projected on its own.
#include "apcs/screens/curve_raster.h"

#include "apcs/animation/motion_path.h"
#include "apcs/raster/painter.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/world_drawing.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace apcs;

namespace {

// The lines through every sample, each projected by to_device and rounded, as a painter draws
// them solid (the path screen's rule: a line that stays on its pixel is not drawn, after the first).
Bitmap painted_one_sample_at_a_time(const SampledCurve& curve, const ViewTransform& view)
{
    Bitmap expected;
    Painter painter(expected, layout::inside_boundary);
    int phase = 0;
    PixelPoint from = view.to_device(curve.sample(0)).rounded();
    for (std::size_t i = 1; i < curve.sample_count(); ++i) {
        const PixelPoint to = view.to_device(curve.sample(i)).rounded();
        if (to == from && phase > 0)
            continue;
        painter.styled_line(from, to, LineStyle::solid, phase);
        from = to;
    }
    return expected;
}

} // namespace

TEST_CASE("the kept curve lights what solid lines through every sample light: runs along rows, slanted lines, "
          "lines leaving the clip, blocks continued",
          "[session][curve]")
{
    // 9000 segments: three blocks. Seen from the front a zigzag in x and y (z still) draws long
    // runs along rows; from above at an angle, slanted lines; zoomed, lines leave the clip.
    ControlPoints points;
    for (int k = 0; k < 9001; ++k)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.0004, std::cos(k * 0.37) * 0.5}, {}});
    const PathSettings settings{{1, 1}, 8, 12, Spacing::nearest};
    const SampledCurve curve = evaluate_path(points, settings).curve;
    std::vector<Vec3> corners;
    for (const ControlPoint& point : points)
        corners.push_back(point.position);
    for (const ViewAngles angles : {ViewAngles{0, 90}, ViewAngles{30, 40}, ViewAngles{-90, 0}}) {
        const ViewTransform fitted = ViewTransform::fit(angles, corners, layout::view_area);
        for (const ViewTransform& view : {fitted, fitted.zoomed(4.0, Vec3{0.0, 1.8, 0.0}, layout::view_area)}) {
            CAPTURE(angles.theta_degrees, angles.phi_degrees, view.focus());
            CurveRaster kept;
            kept.update(curve, view, layout::inside_boundary);
            const Bitmap expected = painted_one_sample_at_a_time(curve, view);
            REQUIRE(kept.pixels().lit_count() > 1000);
            REQUIRE(kept.pixels() == expected);
            // The screen's other way (apcs draw, pictures) draws the same.
            Bitmap drawn;
            Painter painter(drawn, layout::inside_boundary);
            draw_world_curve(painter, curve, view, LineStyle::solid);
            REQUIRE(drawn == expected);
        }
    }
}
