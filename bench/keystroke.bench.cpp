// One staff keystroke, end to end below the terminal: recompute the path (10 control points,
// 32 samples per segment, 12 in-betweens), redraw the path screen's raster, map it to cells and
// diff the cells against the previous grid, at 80x24 and 200x60, for each glyph set.
#include "cell_diff.h"

#include "apcs/screens/path_screen.h"
#include "apcs/raster/screen_layout.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace apcs;

namespace {

ControlPoints ten_points()
{
    ControlPoints points;
    for (int k = 0; k < 10; ++k)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 2.0, std::cos(k * 0.7) * 4.0}, {}});
    return points;
}

void staff_keystroke(benchmark::State& state)
{
    const CellArea area{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
    const auto glyphs = static_cast<GlyphSet>(state.range(2));
    ControlPoints points = ten_points();
    const PathSettings settings{{}, 32, 12, Spacing::nearest};
    EvaluatedPath path = evaluate_path(points, settings);
    PathScreenContent content;
    content.path = &path;
    content.control_points = points;
    const ViewTransform view = path_screen_scene(content).fit({30, 40}, layout::drawing_area);
    AsciiGlyphCache cache;
    CellGrid previous = render_cells(draw_path_screen(content, view), area, glyphs, cache);
    int step = 0;
    for (auto _ : state) {
        const double tension = std::fmod(0.05 * ++step, 2.0) - 1.0;
        for (ControlPoint& point : points)
            point.staff.tension = tension;
        path = evaluate_path(points, settings);
        content.staff.tension = tension;
        content.active_line = StaffLine::tension;
        const CellGrid grid = render_cells(draw_path_screen(content, view), area, glyphs, cache);
        benchmark::DoNotOptimize(bench::changed_cells(previous, grid));
        previous = grid;
    }
}

} // namespace

BENCHMARK(staff_keystroke)
    ->ArgNames({"columns", "rows", "glyphs"})
    ->Args({80, 24, static_cast<int>(GlyphSet::ascii)})
    ->Args({80, 24, static_cast<int>(GlyphSet::braille)})
    ->Args({80, 24, static_cast<int>(GlyphSet::blocks)})
    ->Args({200, 60, static_cast<int>(GlyphSet::ascii)})
    ->Args({200, 60, static_cast<int>(GlyphSet::braille)})
    ->Unit(benchmark::kMillisecond);
