// SPEC §7.2.1: what the path screen shows of a small change — the view filled with the path, the
// zoom, the ghost and the displacement said in numbers.
#include "apcs/formats/dat_file.h"
#include "apcs/formats/path_files.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/graphics_screen.h"
#include "apcs/geometry/hercules.h"
#include "apcs/screens/curve_raster.h"
#include "apcs/editor/path_editor.h"
#include "apcs/raster/screen_layout.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;
using apcs::test::apply;
using apcs::test::LogLines;
namespace cmd = apcs::command;

namespace {

std::string read_data_file(const std::string& name)
{
    std::ifstream in(std::filesystem::path(APCS_SOURCE_DIR) / "data" / name);
    REQUIRE(in);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A shipped path as the session opens it: its points, its SLOPES (else 1 1), the view the
// session's keys type, and both key frames of its folder.
struct ShippedPath {
    std::string folder;
    std::string file;
    ViewAngles angles;
};

PathEditor::Setup shipped_setup(const ShippedPath& shipped)
{
    const Expected<DatFile> file = parse_dat(read_data_file(shipped.folder + "/" + shipped.file), shipped.file);
    REQUIRE(file);
    PathEditor::Setup setup;
    setup.path_name = shipped.file;
    setup.points = control_points_from(*file, {});
    setup.settings.slopes = file->slopes.value_or(EndSlopes{1, 1});
    setup.view_angles = shipped.angles;
    for (const char* key : {"/key1.dat", "/key2.dat"}) {
        const Expected<DatFile> key_file = parse_dat(read_data_file(shipped.folder + key), key);
        REQUIRE(key_file);
        const Graphic graphic = graphic_from(*key_file);
        for (auto& polyline : graphic.polylines(graphic.all_points()))
            setup.key_frame_polylines.push_back(std::move(polyline));
    }
    return setup;
}

// Where the view puts the shown points, in raster pixels.
struct PixelExtent {
    double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
    void add(const DevicePoint& point)
    {
        left = std::min(left, point.x);
        right = std::max(right, point.x);
        top = std::min(top, point.y);
        bottom = std::max(bottom, point.y);
    }
};

PixelExtent shown_extent(const PathEditor& editor, const std::vector<std::vector<Vec3>>& key_frames)
{
    const ViewTransform& view = editor.view_transform();
    PixelExtent extent;
    for (const ControlPoint& point : editor.points())
        extent.add(view.to_device(point.position));
    const SampledCurve& curve = editor.evaluated().curve;
    for (std::size_t s = 0; s < curve.segments.size(); ++s)
        for (int j = 0; j <= curve.samples_per_segment; ++j)
            extent.add(view.to_device(curve.segment_sample(s, static_cast<std::size_t>(j))));
    for (const auto& polyline : key_frames)
        for (const Vec3& point : polyline)
            extent.add(view.to_device(point));
    return extent;
}

// The fill rule: max(w/W, h/H) in drawing cells (9x14 pixels: the raster's text cells, where a
// column is SCF times narrower than a row is tall in pixels of equal aspect); everything at least
// one cell inside the boundary. A projection that stays under 2 cells however magnified (a
// straight path seen end on) is exempt.
void require_filled(const PixelExtent& extent)
{
    const double drawing_columns = double(layout::drawing_area.width()) / hercules::cell_width;
    const double drawing_rows = double(layout::drawing_area.height()) / hercules::cell_height;
    const double width = (extent.right - extent.left) / hercules::cell_width;
    const double height = (extent.bottom - extent.top) / hercules::cell_height;
    CAPTURE(width, height, drawing_columns, drawing_rows);
    // Exempt: a projection under 2 cells (a straight path seen end on).
    if (width < 2.0 && height < 2.0)
        return;
    REQUIRE(std::max(width / drawing_columns, height / drawing_rows) >= 0.8);
    REQUIRE(extent.left >= layout::view_area.left - 0.5);
    REQUIRE(extent.right <= layout::view_area.right + 0.5);
    REQUIRE(extent.top >= layout::view_area.top - 0.5);
    REQUIRE(extent.bottom <= layout::view_area.bottom + 0.5);
}

// The cells of the curve (the raster's lines, no marks, text or staff) that differ between two
// screens at 80x24 braille, leaving out every cell where either screen shows a mark or text.
int changed_curve_cells(const GraphicsScreen& before, const GraphicsScreen& after)
{
    const auto lines_only = [](GraphicsScreen screen) {
        screen.marks.clear();
        screen.text.clear();
        screen.ticked_lines.clear();
        return render_cells(screen, {80, 24}, GlyphSet::braille);
    };
    const CellGrid full_before = render_cells(before, {80, 24}, GlyphSet::braille);
    const CellGrid full_after = render_cells(after, {80, 24}, GlyphSet::braille);
    const CellGrid lines_before = lines_only(before);
    const CellGrid lines_after = lines_only(after);
    int changed = 0;
    for (int row = 0; row < 24; ++row)
        for (int column = 0; column < 80; ++column)
            if (lines_before.at(column, row) != lines_after.at(column, row) &&
                full_before.at(column, row) == lines_before.at(column, row) &&
                full_after.at(column, row) == lines_after.at(column, row))
                ++changed;
    return changed;
}

const std::vector<ShippedPath> shipped_paths{
    {"n-to-l", "way1.dat", {0, 90}},          {"n-to-l", "way4.dat", {0, 90}},
    {"stick", "way1.dat", {40, 50}},          {"stick", "way5.dat", {40, 50}},
    {"snake-apple", "way1.dat", {0, 90}},     {"snake-apple", "way7.dat", {0, 90}},
    {"snake-apple", "session-ani1.dat", {0, 90}}, {"snake-apple", "session-way7.dat", {0, 90}},
};

} // namespace

TEST_CASE("the path screen's view is filled with every shipped path, and with path and keys under K",
          "[session][editor][view]")
{
    for (const ShippedPath& shipped : shipped_paths) {
        for (const ViewAngles angles : {shipped.angles, ViewAngles{}, ViewAngles{-90, 90}, ViewAngles{-90, 0}}) {
            CAPTURE(shipped.folder, shipped.file, angles.theta_degrees, angles.phi_degrees);
            ShippedPath seen = shipped;
            seen.angles = angles;
            const PathEditor::Setup setup = shipped_setup(seen);
            const auto key_frames = setup.key_frame_polylines;
            LogLines log;
            PathEditor editor(setup, log);
            require_filled(shown_extent(editor, {}));
            apply(editor, {cmd::ToggleKeyFrames{}});
            require_filled(shown_extent(editor, key_frames));
        }
    }
}

TEST_CASE("the view stays still while the staff changes the path and is filled again when it is left",
          "[session][editor][view]")
{
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way1.dat", {0, 90}}), log);
    const ViewTransform opened = editor.view_transform();
    // Bias -0.5 swings the curve past control point 2, beyond the points' extent.
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{-10}});
    REQUIRE(editor.view_transform() == opened);
    apply(editor, {cmd::Accept{}});
    REQUIRE(editor.view_transform() == opened);
    apply(editor, {cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::ask_again);
    REQUIRE_FALSE(editor.view_transform() == opened);
    require_filled(shown_extent(editor, {}));
    PathEditor::Setup changed = shipped_setup({"n-to-l", "way1.dat", {0, 90}});
    changed.points = editor.points();
    REQUIRE(PathEditor(changed, log).view_transform() == editor.view_transform());
}

TEST_CASE("after a staff key the message line says how far the curve moved, in units and pixels",
          "[session][editor][view]")
{
    // way1.dat: (0,0,0), (3,-4,5), (0,0,10), slopes 1 1. TENSION +0.05 shortens control point 2's
    // tangent 0.5·(1 − t)·(P3 − P1) = 0.5·(1 − t)·(0,0,10) by (0,0,0.25); the end tangents are the
    // slopes' and stay. Sample to sample the curve moves 0.25·4/27 = 0.037 (at u = 1/3 and 2/3),
    // mostly along itself; a sample's distance from the curve before is at most 0.02654
    // (tests/reference: brute force over 2·33 samples of both curves, every piece): "0.027". The
    // view is filled by height: z runs 0 … 10 over 222 pixel rows, 22 pixels a unit, 0.027 ≈ 0.6
    // pixel: "1 px".
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way1.dat", {0, 90}}), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{+1}});
    REQUIRE(apcs::test::message_of(editor.view()) ==
            "way1.dat: TENSION  control points 1 to 3 of 3  moved up to 0.027 = 1 px");
    // ACCELERATION moves the in-betweens, not the curve.
    apply(editor, {cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{+1}});
    REQUIRE(apcs::test::message_of(editor.view()) ==
            "way1.dat: ACCELERATION  control points 1 to 3 of 3  only the in-betweens moved");
}

TEST_CASE("zoomed x4, three steps of TENSION on way1 change at least 40 cells of the curve at 80x24 braille",
          "[session][editor][view]")
{
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way1.dat", {0, 90}}), log);
    // The curve alone: the ghost (O) would keep the old curve's cells half lit.
    apply(editor, {cmd::ToggleGhost{}, cmd::ChooseGlobal{}});
    const GraphicsScreen fitted = editor.view();
    apply(editor, {cmd::StaffStep{+3}});
    const int fitted_cells = changed_curve_cells(fitted, editor.view());
    apply(editor, {cmd::Undo{}, cmd::Zoom{}});
    REQUIRE(apcs::test::message_of(editor.view()) == "zoom ×2 about the path's middle (Z: more)");
    apply(editor, {cmd::Zoom{}});
    REQUIRE(apcs::test::message_of(editor.view()) == "zoom ×4 about the path's middle (Z: more)");
    const GraphicsScreen zoomed = editor.view();
    // The points the zoom leaves beyond the boundary show no mark (none on the staff rows).
    for (const PixelMark& mark : zoomed.marks)
        if (mark.kind == MarkKind::control_point || mark.kind == MarkKind::inbetween)
            REQUIRE(layout::inside_boundary.contains(mark.at));
    apply(editor, {cmd::StaffStep{+3}});
    const int zoomed_cells = changed_curve_cells(zoomed, editor.view());
    CAPTURE(fitted_cells, zoomed_cells);
    REQUIRE(zoomed_cells >= 40);
    // ×8, then back to the fitted view.
    apply(editor, {cmd::Zoom{}, cmd::Zoom{}});
    REQUIRE(apcs::test::message_of(editor.view()) == "zoom off: the view fitted to the path");
    PathEditor::Setup changed = shipped_setup({"n-to-l", "way1.dat", {0, 90}});
    changed.points = editor.points();
    REQUIRE(PathEditor(changed, log).view_transform() == editor.view_transform());
}

TEST_CASE("Z zooms about the picked region: its middle comes to the middle of the view", "[session][editor][view]")
{
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way4.dat", {0, 90}}), log);
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{1}, cmd::ArrowMove{1}, cmd::Accept{}, cmd::Accept{}, cmd::Zoom{}});
    REQUIRE(apcs::test::message_of(editor.view()) == "zoom ×2 about control point 2 (Z: more)");
    const DevicePoint at = editor.view_transform().to_device(editor.points()[1].position);
    REQUIRE(at.x == Approx((layout::view_area.left + layout::view_area.right) / 2.0));
    REQUIRE(at.y == Approx((layout::view_area.top + layout::view_area.bottom) / 2.0));
}

namespace {

// Pixels lit in `screen` and not in `without`.
std::size_t pixels_beyond(const Bitmap& screen, const Bitmap& without, const Bitmap* within = nullptr)
{
    std::size_t count = 0;
    for (int y = 0; y < screen.height(); ++y)
        for (int x = 0; x < screen.width(); ++x)
            if (screen.get(x, y) && !without.get(x, y) && (within == nullptr || within->get(x, y)))
                ++count;
    return count;
}

} // namespace

TEST_CASE("the curve before the last staff key stays as a dotted ghost until the next line — O toggles it",
          "[session][editor][view]")
{
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way1.dat", {0, 90}}), log);
    apply(editor, {cmd::ChooseGlobal{}});
    const Bitmap before = editor.view().bitmap;
    apply(editor, {cmd::StaffStep{-6}});
    const GraphicsScreen with_ghost = editor.view();
    apply(editor, {cmd::ToggleGhost{}});
    REQUIRE(apcs::test::message_of(editor.view()) == "ghost hidden (O shows it)");
    const GraphicsScreen without_ghost = editor.view();
    // The ghost's pixels are the old curve's, and only some of them: dotted.
    const std::size_t ghost = pixels_beyond(with_ghost.bitmap, without_ghost.bitmap);
    const std::size_t old_curve = pixels_beyond(before, without_ghost.bitmap);
    CAPTURE(ghost, old_curve);
    REQUIRE(ghost > 50);
    REQUIRE(pixels_beyond(with_ghost.bitmap, without_ghost.bitmap, &before) == ghost);
    REQUIRE(ghost < old_curve * 3 / 4);
    // Seen at 80x24 braille: cells of the ghost, not one curve drawn over the other.
    REQUIRE(changed_curve_cells(without_ghost, with_ghost) >= 10);
    apply(editor, {cmd::ToggleGhost{}});
    REQUIRE(apcs::test::message_of(editor.view()) == "ghost shown: the curve before the last change, dotted");
    REQUIRE(editor.view().bitmap == with_ghost.bitmap);
    // The next line: gone.
    apply(editor, {cmd::Accept{}});
    REQUIRE(pixels_beyond(editor.view().bitmap, without_ghost.bitmap) == 0);
}

TEST_CASE("a waypoint edit leaves the curve before it as a ghost", "[session][editor][view]")
{
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way1.dat", {0, 90}}), log);
    apply(editor, {cmd::OpenWaypoints{}, cmd::ChoosePoint{+1}});
    const Bitmap before = editor.view().bitmap;
    apply(editor, {cmd::MovePoint{+3, 0, 0}});
    const Bitmap with_ghost = editor.view().bitmap;
    apply(editor, {cmd::ToggleGhost{}});
    const Bitmap without_ghost = editor.view().bitmap;
    const std::size_t ghost = pixels_beyond(with_ghost, without_ghost);
    REQUIRE(ghost > 50);
    REQUIRE(pixels_beyond(with_ghost, without_ghost, &before) == ghost);
}

namespace {

// The curve of `points` as the path screen draws it in `view`.
Bitmap curve_pixels(const ControlPoints& points, const PathSettings& settings, const ViewTransform& view)
{
    CurveRaster curve;
    curve.update(evaluate_path(points, settings).curve, view, layout::inside_boundary);
    return curve.pixels();
}

// The ghost's pixels now: those that O takes away.
Bitmap ghost_pixels(PathEditor& editor)
{
    const Bitmap with_ghost = editor.view().bitmap;
    apply(editor, {cmd::ToggleGhost{}});
    const Bitmap without_ghost = editor.view().bitmap;
    apply(editor, {cmd::ToggleGhost{}});
    Bitmap ghost(with_ghost.width(), with_ghost.height());
    for (int y = 0; y < ghost.height(); ++y)
        for (int x = 0; x < ghost.width(); ++x)
            if (with_ghost.get(x, y) && !without_ghost.get(x, y))
                ghost.set(x, y, true);
    return ghost;
}

} // namespace

TEST_CASE("the ghost stays through Z and K, drawn again in the new view from the path before the change",
          "[session][editor][view]")
{
    LogLines log;
    const PathEditor::Setup setup = shipped_setup({"n-to-l", "way1.dat", {0, 90}});
    const ControlPoints before = setup.points;
    PathEditor editor(setup, log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{-6}});
    const Bitmap fitted_ghost = ghost_pixels(editor);
    REQUIRE(pixels_beyond(fitted_ghost, Bitmap(fitted_ghost.width(), fitted_ghost.height())) > 50);
    for (const Command& view_key : std::vector<Command>{cmd::Zoom{}, cmd::Zoom{}, cmd::ToggleKeyFrames{}}) {
        apply(editor, {view_key});
        const Bitmap ghost = ghost_pixels(editor);
        const Bitmap old_curve = curve_pixels(before, setup.settings, editor.view_transform());
        const Bitmap empty(ghost.width(), ghost.height());
        CAPTURE(apcs::test::message_of(editor.view()));
        // Dotted, every dot on the old curve in this view, and a new picture, not the last one.
        REQUIRE(pixels_beyond(ghost, empty) > 50);
        REQUIRE(pixels_beyond(ghost, empty, &old_curve) == pixels_beyond(ghost, empty));
        REQUIRE(ghost != fitted_ghost);
    }
    // Undo: the ghost is the curve the key made, and it too follows the view.
    apply(editor, {cmd::Undo{}, cmd::Zoom{}});
    CHECK(apcs::test::message_of(editor.view()) == "zoom ×8 about the path's middle (Z: more)");
    PathEditor changed_editor(setup, log);
    apply(changed_editor, {cmd::ChooseGlobal{}, cmd::StaffStep{-6}});
    const Bitmap ghost = ghost_pixels(editor);
    const Bitmap key_curve = curve_pixels(changed_editor.points(), setup.settings, editor.view_transform());
    const Bitmap empty(ghost.width(), ghost.height());
    REQUIRE(pixels_beyond(ghost, empty) > 50);
    REQUIRE(pixels_beyond(ghost, empty, &key_curve) == pixels_beyond(ghost, empty));
}

TEST_CASE("the waypoint editor's ghost follows its zoom", "[session][editor][view]")
{
    LogLines log;
    const PathEditor::Setup setup = shipped_setup({"n-to-l", "way1.dat", {0, 90}});
    PathEditor editor(setup, log);
    apply(editor, {cmd::OpenWaypoints{}, cmd::ChoosePoint{+1}, cmd::MovePoint{+3, 0, 0}, cmd::Zoom{}});
    REQUIRE(apcs::test::message_of(editor.view()).find("zoom ×2 about control point 2") != std::string::npos);
    const Bitmap ghost = ghost_pixels(editor);
    const Bitmap old_curve = curve_pixels(setup.points, setup.settings, editor.view_transform());
    const Bitmap empty(ghost.width(), ghost.height());
    REQUIRE(pixels_beyond(ghost, empty) > 50);
    REQUIRE(pixels_beyond(ghost, empty, &old_curve) == pixels_beyond(ghost, empty));
}

TEST_CASE("an exercise's goal point is marked @ where the view shows it, in the goal's colour", "[session][editor][view]")
{
    LogLines log;
    PathEditor editor(shipped_setup({"n-to-l", "way1.dat", {0, 90}}), log);
    // exercise-4-near.keys: the first chord's middle.
    const Vec3 goal{1.5, -2.0, 2.5};
    const GraphicsScreen marked = editor.view(goal);
    const auto is_goal = [](const PixelMark& mark) { return mark.kind == MarkKind::goal; };
    REQUIRE(std::count_if(marked.marks.begin(), marked.marks.end(), is_goal) == 1);
    const PixelMark& mark = *std::find_if(marked.marks.begin(), marked.marks.end(), is_goal);
    REQUIRE(mark.at == editor.view_transform().to_device(goal).rounded());
    REQUIRE(mark.role == ColourRole::goal);
    const CellGrid cells = render_cells(marked, {80, 24}, GlyphSet::ascii);
    const int column = cell_of_pixel(mark.at.x, marked.bitmap.width(), 80);
    const int row = cell_of_pixel(mark.at.y, marked.bitmap.height(), 24);
    REQUIRE(cells.at(column, row) == U'@');
    REQUIRE(cells.role_at(column, row) == ColourRole::goal);
    // No goal, no mark; a goal the view does not show, no mark on the boundary or the staff.
    const GraphicsScreen unmarked = editor.view();
    REQUIRE(std::none_of(unmarked.marks.begin(), unmarked.marks.end(), is_goal));
    const GraphicsScreen far_away = editor.view(Vec3{0.0, 1000.0, 0.0});
    REQUIRE(std::none_of(far_away.marks.begin(), far_away.marks.end(), is_goal));
}
