#include "apcs/screens/path_screen.h"
#include "apcs/raster/screen_layout.h"

#include "support/golden.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

using namespace apcs;

namespace {

struct Example {
    ControlPoints points;
    EvaluatedPath path;
    GraphicsScreen screen;
};

Example example_screen()
{
    Example example;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{3, -4, 5}, Vec3{0, 0, 10}})
        example.points.push_back({position, {0.25, 0, -0.5, 0}});
    example.path = evaluate_path(example.points, {{}, 32, 12, Spacing::nearest});
    PathScreenContent content = path_screen_content(example.points, example.path);
    content.active_line = StaffLine::continuity;
    content.message = "4/6 step  J/L 3 steps  Enter accept  Esc keep";
    const ViewTransform view = path_screen_scene(content).fit({30, 40}, layout::view_area);
    example.screen = draw_path_screen(content, view);
    return example;
}

} // namespace

TEST_CASE("the path screen in each glyph set matches its approved cell grid", "[session][screen]")
{
    const Example example = example_screen();
    test::check_golden("path_screen_ascii.txt", render_cells(example.screen, {80, 24}, GlyphSet::ascii).to_text());
    test::check_golden("path_screen_braille.txt", render_cells(example.screen, {80, 24}, GlyphSet::braille).to_text());
    test::check_golden("path_screen_blocks.txt", render_cells(example.screen, {80, 24}, GlyphSet::blocks).to_text());
}

TEST_CASE("the path screen at 200x60 in each glyph set matches its approved cell grid", "[session][screen]")
{
    const Example example = example_screen();
    test::check_golden("path_screen_200x60_ascii.txt", render_cells(example.screen, {200, 60}, GlyphSet::ascii).to_text());
    test::check_golden("path_screen_200x60_braille.txt",
                       render_cells(example.screen, {200, 60}, GlyphSet::braille).to_text());
    test::check_golden("path_screen_200x60_blocks.txt", render_cells(example.screen, {200, 60}, GlyphSet::blocks).to_text());
}

TEST_CASE("each staff line is one row of characters beside its label at any size, a tick at -1, 0 and +1",
          "[session][screen]")
{
    const Example example = example_screen();
    for (const CellArea area : {CellArea{80, 24}, CellArea{100, 30}, CellArea{133, 40}, CellArea{200, 60}, CellArea{240, 72}})
        for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille, GlyphSet::blocks}) {
            CAPTURE(area.columns, static_cast<int>(glyphs));
            const CellGrid grid = render_cells(example.screen, area, glyphs);
            const TickedLineGlyphs shown = ticked_line_glyphs(glyphs);
            const auto column_of = [&](int pixel) { return cell_of_pixel(pixel, 720, area.columns); };
            const int first = column_of(layout::staff_left);
            const int last = column_of(layout::staff_right);
            const int message = cell_of_pixel(hercules::text_row_top(layout::message_row) + 7, 348, area.rows);
            const int keys = cell_of_pixel(hercules::text_row_top(layout::key_help_row) + 7, 348, area.rows);
            std::vector<int> label_rows;
            for (int line = 0; line < 4; ++line)
                label_rows.push_back(cell_of_pixel(layout::staff_line_y(line), 348, area.rows));
            for (int row = message + 1; row < keys; ++row) {
                const bool label_row = std::find(label_rows.begin(), label_rows.end(), row) != label_rows.end();
                for (int column = first; column <= last; ++column) {
                    const char32_t glyph = grid.at(column, row);
                    CAPTURE(row, column, static_cast<std::uint32_t>(glyph));
                    if (!label_row) {
                        REQUIRE(glyph == U' '); // no tick spills into the rows between the lines
                        continue;
                    }
                    if (glyph == U'O')
                        continue;
                    if (column == first)
                        REQUIRE(glyph == shown.first);
                    else if (column == last)
                        REQUIRE(glyph == shown.last);
                    else if (column == column_of(layout::staff_x(0.0)))
                        REQUIRE(glyph == shown.crossing);
                    else
                        REQUIRE(glyph == shown.line);
                }
            }
        }
}

TEST_CASE("the staff is as light in blocks as in braille: one thin line, no half blocks", "[session][screen]")
{
    const CellGrid grid = render_cells(example_screen().screen, {80, 24}, GlyphSet::blocks);
    for (int row = layout::first_staff_row; row < layout::first_staff_row + 4; ++row)
        for (int column = 0; column < 80; ++column) {
            CAPTURE(row, column);
            REQUIRE((grid.at(column, row) < U'\u2580' || grid.at(column, row) > U'\u259F'));
        }
    REQUIRE(grid.row_text(19).substr(grid.row_text(19).find("\u251C"), 6) == "\u251C\u2500");
}

TEST_CASE("the path screen shows the staff values and the active line", "[session][screen]")
{
    const CellGrid grid = render_cells(example_screen().screen, {80, 24}, GlyphSet::ascii);
    REQUIRE(grid.row_text(19).starts_with(" TENSION"));
    REQUIRE(grid.row_text(20).starts_with(">CONTINUITY"));
    REQUIRE(grid.row_text(19).substr(69, 5) == "+0.25");
    REQUIRE(grid.row_text(21).substr(69, 5) == "-0.50");
}

TEST_CASE("every control point shows as x in the cells", "[session][screen]")
{
    const Example example = example_screen();
    std::size_t crosses = 0;
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille}) {
        const CellGrid grid = render_cells(example.screen, {80, 24}, glyphs);
        crosses = 0;
        for (int row = 0; row < 18; ++row)
            for (int column = 0; column < 80; ++column)
                crosses += grid.at(column, row) == U'x' ? 1u : 0u;
        REQUIRE(crosses == 3);
    }
}

TEST_CASE("staff values are shown with a sign and two decimals", "[session][screen]")
{
    REQUIRE(format_staff_value(0.0) == "+0.00");
    REQUIRE(format_staff_value(-0.0000001) == "+0.00");
    REQUIRE(format_staff_value(0.05) == "+0.05");
    REQUIRE(format_staff_value(-1.0) == "-1.00");
}

namespace {

// The grid's text, then its styles: one character a cell, '.' plain, 'B' bold, 'R' reverse.
std::string text_and_styles(const CellGrid& grid)
{
    std::string text = grid.to_text() + "-- styles\n";
    for (int row = 0; row < grid.rows(); ++row) {
        for (int column = 0; column < grid.columns(); ++column) {
            const CellStyle style = grid.style_at(column, row);
            text += style == CellStyle::reverse ? 'R' : style == CellStyle::bold ? 'B' : '.';
        }
        text += '\n';
    }
    return text;
}

GraphicsScreen picking_screen(std::optional<std::size_t> arrow)
{
    ControlPoints points;
    for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{0, 3, 4}, Vec3{0, 7, 1}, Vec3{0, 10, 6}})
        points.push_back({position, {}});
    static EvaluatedPath path;
    path = evaluate_path(points, {{}, 32, 12, Spacing::nearest});
    PathScreenContent content = path_screen_content(points, path);
    content.region = ControlRegion{1, 2};
    content.arrow_at = arrow;
    content.arrow_home = !arrow;
    content.active_line = StaffLine::tension;
    content.message = "way1.dat: TENSION  control points 2 to 3 of 4";
    const ViewTransform view = path_screen_scene(content).fit({0, 90}, layout::view_area);
    return draw_path_screen(content, view);
}

int count_of(const CellGrid& grid, char32_t glyph)
{
    int count = 0;
    for (int row = 0; row < 18; ++row)
        for (int column = 0; column < grid.columns(); ++column)
            count += grid.at(column, row) == glyph ? 1 : 0;
    return count;
}

} // namespace

TEST_CASE("at 80x24 the arrow, the picked region and the in-betweens are characters in every glyph set",
          "[session][screen]")
{
    const GraphicsScreen screen = picking_screen(2);
    for (const auto& [glyphs, name] : {std::pair{GlyphSet::ascii, "ascii"}, std::pair{GlyphSet::braille, "braille"},
                                       std::pair{GlyphSet::blocks, "blocks"}}) {
        const CellGrid grid = render_cells(screen, {80, 24}, glyphs);
        test::check_golden(std::string("path_screen_region_") + name + ".txt", text_and_styles(grid));
        CAPTURE(name);
        REQUIRE(count_of(grid, U'x') == 4);
        REQUIRE(count_of(grid, mark_glyph(MarkKind::arrow, glyphs)) == 1);
        // Twelve in-betweens: each a mark, or counted in a digit where two share a cell.
        int inbetweens = count_of(grid, mark_glyph(MarkKind::inbetween, glyphs));
        for (char32_t digit = U'2'; digit <= U'9'; ++digit)
            inbetweens += count_of(grid, digit) * static_cast<int>(digit - U'0');
        REQUIRE(inbetweens <= 12);
        REQUIRE(inbetweens >= 10); // two may hide under control points' x
        // The picked points 2 and 3 are reverse video, the others not; the active label too.
        int reversed = 0;
        for (int row = 0; row < 18; ++row)
            for (int column = 0; column < 80; ++column)
                reversed += grid.style_at(column, row) == CellStyle::reverse ? 1 : 0;
        REQUIRE(reversed == 2);
        REQUIRE(grid.style_at(1, 19) == CellStyle::reverse);
        REQUIRE(grid.style_at(1, 20) == CellStyle::plain);
    }
}

TEST_CASE("the arrow waits at the top-left before it moves", "[session][screen]")
{
    const CellGrid grid = render_cells(picking_screen(std::nullopt), {80, 24}, GlyphSet::ascii);
    REQUIRE(grid.at(1, 1) == U'>');
}

TEST_CASE("moving acceleration from 0 to +1 moves the in-between marks on screen at 80x24", "[session][screen]")
{
    const auto marks_at = [](double acceleration) {
        ControlPoints points;
        for (const Vec3& position : {Vec3{0, 0, 0}, Vec3{0, 3, 4}, Vec3{0, 7, 1}, Vec3{0, 10, 6}})
            points.push_back({position, {0, 0, 0, acceleration}});
        const EvaluatedPath path = evaluate_path(points, {{}, 32, 12, Spacing::nearest});
        const PathScreenContent content = path_screen_content(points, path);
        // One view for both, as the session keeps it while the staff moves.
        static const ViewTransform view = path_screen_scene(content).fit({0, 90}, layout::view_area);
        const CellGrid grid = render_cells(draw_path_screen(content, view), {80, 24}, GlyphSet::ascii);
        std::vector<std::pair<int, int>> cells;
        for (int row = 0; row < 18; ++row)
            for (int column = 0; column < 80; ++column)
                if (grid.at(column, row) == U'*' || (grid.at(column, row) >= U'2' && grid.at(column, row) <= U'9'))
                    cells.emplace_back(column, row);
        return cells;
    };
    const auto still = marks_at(0.0);
    const auto accelerated = marks_at(1.0);
    REQUIRE(still.size() >= 8);
    // Most marks stand in other cells: the change is seen, not one cell's smudge.
    int moved = 0;
    for (const auto& cell : accelerated)
        moved += std::find(still.begin(), still.end(), cell) == still.end() ? 1 : 0;
    REQUIRE(moved >= static_cast<int>(still.size()) / 2);
}

TEST_CASE("a long curve drawn segment by segment is pixel for pixel its samples drawn as a polyline",
          "[session][drawing]")
{
    // 20000 control points on a slow loop: most segments lie on a single pixel and are passed over
    // by their hull; the picture must not change, dashes included.
    ControlPoints points;
    for (int k = 0; k < 20000; ++k)
        points.push_back({{std::sin(k * 0.0007) * 3.0, std::cos(k * 0.0011) * 2.0, std::sin(k * 0.0005)}, {}});
    const EvaluatedPath path = evaluate_path(points, PathSettings{});
    const ViewTransform view = ViewScene().add(path.curve).fit({30, 40}, layout::drawing_area);
    // The case the hull is for must be most of this curve, or the test proves nothing about it.
    const auto on_one_pixel = [&view](const HermiteSegment& segment) {
        const PixelPoint start = view.to_device(segment.start).rounded();
        for (const Vec3& point : {segment.start + segment.start_tangent * (1.0 / 3.0),
                                  segment.end - segment.end_tangent * (1.0 / 3.0), segment.end})
            if (view.to_device(point).rounded() != start)
                return false;
        return true;
    };
    REQUIRE(std::count_if(path.curve.segments.begin(), path.curve.segments.end(), on_one_pixel) > 15000);
    // And a segment whose two ends share a pixel but which swings far out between them (its
    // neighbours make its tangents long): only its hull, not its ends, may pass it over.
    const ControlPoints swinging{
        {{0, -20, 0}, {}}, {{0, 0, 0}, {}}, {{0, 0.0001, 0}, {}}, {{0, 10, 5}, {}}, {{0, 20, 0}, {}}};
    const EvaluatedPath swing = evaluate_path(swinging, PathSettings{});
    const ViewTransform swing_view = ViewScene().add(swing.curve).fit({0, 90}, layout::drawing_area);
    for (const LineStyle style : {LineStyle::solid, LineStyle::dashed}) {
        Bitmap by_samples;
        Bitmap by_segments;
        Painter samples_painter(by_samples);
        Painter segments_painter(by_segments);
        draw_world_polyline(samples_painter, swing.curve.samples(), swing_view, style);
        draw_world_curve(segments_painter, swing.curve, swing_view, style);
        REQUIRE(by_segments == by_samples);
    }
    for (const LineStyle style : {LineStyle::solid, LineStyle::dashed, LineStyle::dotted}) {
        CAPTURE(static_cast<int>(style));
        Bitmap by_samples;
        Bitmap by_segments;
        std::vector<Stroke> sample_strokes;
        std::vector<Stroke> segment_strokes;
        Painter samples_painter(by_samples);
        samples_painter.record_into(sample_strokes);
        Painter segments_painter(by_segments);
        segments_painter.record_into(segment_strokes);
        draw_world_polyline(samples_painter, path.curve.samples(), view, style);
        draw_world_curve(segments_painter, path.curve, view, style);
        REQUIRE(by_segments == by_samples);
        REQUIRE(by_samples.lit_count() > 500);
        REQUIRE(segment_strokes.size() == sample_strokes.size());
    }
}

TEST_CASE("of many control point marks on one pixel the last is kept, boxed first when an earlier was",
          "[session][screen]")
{
    // 5000 runs on pixels of their own, then one more on the first run's pixel, out of the region.
    std::vector<ControlPointRun> runs;
    for (int i = 0; i < 5000; ++i)
        runs.push_back({{10 + i % 700, 10 + i / 700}, static_cast<std::size_t>(i), static_cast<std::size_t>(i)});
    runs.push_back({{10, 10}, 5000, 5000});
    runs.push_back({{-3, 20}, 5001, 5001}); // off the raster: kept as it is
    const std::vector<PixelMark> marks = control_point_marks(runs, ControlRegion{0, 0});
    REQUIRE(marks.size() == 5002);
    CHECK(marks.front().at == PixelPoint{11, 10}); // the first pixel's marks moved to its last
    CHECK(marks[4999].at == PixelPoint{10, 10});
    CHECK(marks[4999].style == CellStyle::reverse);
    CHECK(marks[5000].at == PixelPoint{10, 10});
    CHECK(marks[5000].style == CellStyle::plain);
    CHECK(marks[5001].at == PixelPoint{-3, 20});
    // Few marks are laid as they come.
    const std::vector<PixelMark> few = control_point_marks(std::span(runs).first(10), std::nullopt);
    CHECK(few.size() == 10);
}

TEST_CASE("control point runs updated around inserted, deleted and moved points are the runs made afresh",
          "[session][path]")
{
    ControlPoints points;
    for (int k = 0; k < 3000; ++k) // runs of a few points on one pixel, and points of their own
        points.push_back({{std::sin(k * 0.9) * (k % 7 == 0 ? 3.0 : 0.001), k * 0.0005, 0.0}, {}});
    for (int k = 1000; k < 1300; ++k) // and a run of 300 on one pixel, split and joined inside
        points[static_cast<std::size_t>(k)].position = {0.0, 0.5, 0.0};
    const ViewTransform view = ViewTransform::fit({0, 90}, std::vector<Vec3>{{-3, 0, -1}, {3, 1.5, 1}}, {0, 0, 720, 259});
    std::vector<ControlPointRun> runs = control_point_runs(points, view);
    const auto same_runs = [](const std::vector<ControlPointRun>& left, const std::vector<ControlPointRun>& right) {
        REQUIRE(left.size() == right.size());
        for (std::size_t r = 0; r < left.size(); ++r) {
            CAPTURE(r);
            REQUIRE(left[r].at == right[r].at);
            REQUIRE(left[r].first == right[r].first);
            REQUIRE(left[r].last == right[r].last);
        }
    };
    const std::vector<PathChange> changes{{0, 0, 1},    {1, 1, 0},    {700, 1, 1},  {1400, 0, 1}, {1401, 1, 0},
                                          {2999, 0, 1}, {3000, 1, 0}, {5, 1, 1},    {1100, 0, 1}, {1150, 1, 1},
                                          {1150, 1, 1}, {1101, 1, 0}, {1000, 0, 1}, {1299, 1, 0}, {1200, 0, 1}};
    for (const PathChange& change : changes) {
        CAPTURE(change.first, change.removed, change.inserted);
        const auto at = points.begin() + static_cast<std::ptrdiff_t>(change.first);
        if (change.inserted > change.removed)
            points.insert(at, ControlPoint{{0.5, static_cast<double>(change.first) * 0.0005, 0.0}, {}});
        else if (change.removed > change.inserted)
            points.erase(at);
        else
            at->position = at->position + Vec3{0.0, 0.0005, 0.0};
        update_control_point_runs(runs, points, view, change);
        same_runs(runs, control_point_runs(points, view));
    }
}

namespace {

// The view fitted to the control points and then every sample, visited one by one in order.
ViewTransform fitted_to_every_point(ViewAngles angles, const ControlPoints& points, const std::vector<Vec3>& samples)
{
    return ViewTransform::fit_visiting(
        angles,
        [&](const auto& visit) {
            for (const ControlPoint& point : points)
                visit(point.position);
            for (const Vec3& sample : samples)
                visit(sample);
        },
        layout::view_area);
}

} // namespace

TEST_CASE("a scene's view, fitted past the segments that cannot reach further, is the view fitted to every sample",
          "[session][path]")
{
    for (const double wiggle : {0.001, 0.5, 4.0}) {
        CAPTURE(wiggle);
        ControlPoints points;
        for (int k = 0; k < 3000; ++k) // a trajectory, a scribble and between, cusps included
            points.push_back({{std::sin(k * 0.9) * 3.0, k * wiggle, std::cos(k * 0.7) * wiggle},
                              {k % 5 == 0 ? -1.0 : 0.3, std::sin(k * 0.2), 0.0, 0.0}});
        const EvaluatedPath path = evaluate_path(points, {{1, 1}, 16, 12, Spacing::nearest});
        ViewScene scene;
        scene.add(std::span<const ControlPoint>(points)).add(path.curve);
        const std::vector<Vec3> every = path.curve.samples();
        for (const ViewAngles angles : {ViewAngles{30, 40}, ViewAngles{0, 90}, ViewAngles{-70, 10}}) {
            REQUIRE(scene.fit(angles, layout::view_area) == fitted_to_every_point(angles, points, every));
        }
        BoundingBox box;
        for (const Vec3& sample : every)
            box.add(sample);
        REQUIRE(scene.bounds().low() == box.low());
        REQUIRE(scene.bounds().high() == box.high());
    }
}

TEST_CASE("a long scene's view gathered on both cores is the view gathered point by point in order", "[session][path]")
{
    // Enough segments and points (2 x 2^14 and more) for every list to be gone over in two halves.
    ControlPoints points;
    for (int k = 0; k < 40000; ++k)
        points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.5, std::cos(k * 0.7) * 4.0}, {k % 7 == 0 ? -1.0 : 0.2, 0, 0, 0}});
    const EvaluatedPath path = evaluate_path(points, {{1, 1}, 8, 12, Spacing::nearest});
    ViewScene scene;
    scene.add(std::span<const ControlPoint>(points)).add(path.curve);
    const std::vector<Vec3> every = path.curve.samples();
    BoundingBox box;
    for (const ControlPoint& point : points)
        box.add(point.position);
    for (const Vec3& sample : every)
        box.add(sample);
    REQUIRE(scene.bounds().low() == box.low());
    REQUIRE(scene.bounds().high() == box.high());
    for (const ViewAngles angles : {ViewAngles{30, 40}, ViewAngles{0, 90}}) {
        ViewTransform filled = ViewTransform::centred_on(angles, box, layout::view_area);
        ProjectedExtent extent;
        for (const ControlPoint& point : points)
            extent.add(filled.to_eye(point.position));
        for (const Vec3& sample : every)
            extent.add(filled.to_eye(sample));
        filled.fill(extent, layout::view_area);
        REQUIRE(scene.fill(angles, layout::view_area) == filled);
        REQUIRE(scene.fit(angles, layout::view_area) == fitted_to_every_point(angles, points, every));
    }
}
