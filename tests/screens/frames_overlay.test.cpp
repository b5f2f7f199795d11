#include "apcs/screens/frames_overlay.h"

#include "apcs/raster/svg_encoder.h"
#include "apcs/playback/animation_player.h"
#include "apcs/raster/glyph_mapper.h"
#include "apcs/raster/screen_layout.h"
#include "apcs/screens/short_screen.h"
#include "apcs/base/step_log.h"

#include "support/xml_elements.h"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

using namespace apcs;

namespace {

// Three frames of one straight part, seen face-on (θ = 0, Φ = 90: y to the right, z up): frame 0
// at z = 10, frame 1 at z = 5, frame 2 at z = 0, each from y = 0 to y = 20, so that each frame is
// one raster row of its own.
constexpr ViewAngles face_on{0, 90};

FrameSequence three_levels()
{
    FrameSequence frames(3, 2);
    for (std::size_t k = 0; k < 3; ++k) {
        const double z = 10.0 - 5.0 * static_cast<double>(k);
        frames.frame(k)[0] = {0, 0, z};
        frames.frame(k)[1] = {0, 20, z};
    }
    return frames;
}

Graphic one_line() { return {{{"line", Closure::open, {{0, 0, 10}, {0, 20, 10}}}}}; }

struct Row {
    int y = 0;
    int left = 0;
    int right = 0;
};

// Where frame k's line lies in the raster: one row, from its left end to its right.
Row row_of(const FrameSequence& frames, std::size_t k)
{
    const ViewTransform view = frames_view(frames, face_on);
    const PixelPoint from = view.to_device(frames.frame(k)[0]).rounded();
    const PixelPoint to = view.to_device(frames.frame(k)[1]).rounded();
    REQUIRE(from.y == to.y);
    REQUIRE(to.x - from.x > 100);
    return {from.y, from.x, to.x};
}

// The x of every lit pixel of `row`, left to right.
std::vector<int> lit_along(const Bitmap& bitmap, const Row& row)
{
    std::vector<int> lit;
    for (int x = row.left; x <= row.right; ++x)
        if (bitmap.get(x, row.y))
            lit.push_back(x);
    return lit;
}

// The pixels the PNG lights along a styled line from `left`, as Painter draws it: dashed 6 on 4
// off, dotted 1 on 2 off, the pattern starting at the line's first pixel.
std::vector<int> pattern_from(int left, int right, int on, int period)
{
    std::vector<int> lit;
    for (int x = left; x <= right; ++x)
        if ((x - left) % period < on)
            lit.push_back(x);
    return lit;
}

GraphicsScreen three_levels_overlay()
{
    const FrameSequence frames = three_levels();
    return frames_overlay_screen(frames, one_line(), face_on, "3 frames overlaid",
                                 {key_frames_names("key1.dat", "key2.dat", 3), {}, {}, false, {}});
}

// The legend's row as it reads: its parts, each in the colour of its frames, one after the other.
std::string legend_of(const GraphicsScreen& screen)
{
    std::string legend;
    for (const TextLine& line : screen.text)
        if (line.row == overlay_legend_row)
            legend += line.text;
    return legend;
}

// The raster x of each lit run of an SVG stroke's path data ("Mx,y Lx,y" or a dot "Mx,y Vy"),
// first and last pixel.
std::vector<std::pair<int, int>> svg_runs(const std::string& data)
{
    std::vector<std::pair<int, int>> runs;
    std::size_t at = data.find('M');
    while (at != std::string::npos) {
        const std::size_t next = data.find('M', at + 1);
        const std::string run = data.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
        const int first = static_cast<int>(std::strtod(run.c_str(), nullptr) - 0.5);
        const std::size_t line_to = run.rfind('L');
        const int last = line_to == std::string::npos ? first
                                                      : static_cast<int>(std::strtod(run.c_str() + line_to + 1, nullptr) - 0.5);
        runs.emplace_back(first, last);
        at = next;
    }
    return runs;
}

// The lit pixels of `row` as runs of neighbours, first and last pixel.
std::vector<std::pair<int, int>> bitmap_runs(const Bitmap& bitmap, const Row& row)
{
    std::vector<std::pair<int, int>> runs;
    for (const int x : lit_along(bitmap, row)) {
        if (!runs.empty() && runs.back().second == x - 1)
            runs.back().second = x;
        else
            runs.emplace_back(x, x);
    }
    return runs;
}

std::string path_data_of_class(const std::string& svg, const std::string& style_class)
{
    const auto elements = test::XmlReader::read(svg);
    REQUIRE(elements);
    for (const test::XmlElement& path : test::elements_named(*elements, "path"))
        if (path.attributes.at("class") == style_class)
            return path.attributes.at("d");
    FAIL("no path of class " << style_class);
    return {};
}

} // namespace

TEST_CASE("an overlay of frames draws the first solid, the last dashed and the ones between dotted", "[session][overlay]")
{
    const FrameSequence frames = three_levels();
    const GraphicsScreen screen = three_levels_overlay();
    const Row first = row_of(frames, 0);
    const Row between = row_of(frames, 1);
    const Row last = row_of(frames, 2);
    CHECK(lit_along(screen.bitmap, first) == pattern_from(first.left, first.right, 1, 1));
    CHECK(lit_along(screen.bitmap, between) == pattern_from(between.left, between.right, 1, 3));
    CHECK(lit_along(screen.bitmap, last) == pattern_from(last.left, last.right, 6, 10));
    // About all, a third and three fifths of the line's pixels.
    const auto length = static_cast<std::size_t>(first.right - first.left + 1);
    CHECK(lit_along(screen.bitmap, first).size() == length);
    CHECK(lit_along(screen.bitmap, between).size() == (length + 2) / 3);
    CHECK(lit_along(screen.bitmap, last).size() * 10 >= length * 6 - 10);
}

TEST_CASE("an overlay's legend names its strokes under the caption, each part in the colour of its frames",
          "[session][overlay][colour]")
{
    const GraphicsScreen screen = three_levels_overlay();
    REQUIRE(screen.text.size() == 4);
    CHECK(screen.text[0].row == layout::message_row);
    CHECK(screen.text[0].text == "3 frames overlaid");
    std::string legend;
    for (std::size_t part = 1; part < 4; ++part) {
        CHECK(screen.text[part].row == overlay_legend_row);
        CHECK(screen.text[part].column == 1 + static_cast<int>(legend.size()));
        CHECK(screen.text[part].role == overlay_role(part == 1 ? 0 : part == 2 ? 2 : 1, 3));
        legend += screen.text[part].text;
    }
    CHECK(legend == "solid: KEY1 key1.dat  dashed: KEY2 key2.dat  dotted: 1 in-between");
}

TEST_CASE("an overlay's first, last and middle frames are told apart in colour in every glyph set on an 80x23 pane, "
          "where braille and blocks draw a dash or a dot as a line",
          "[session][overlay][colour]")
{
    CHECK(overlay_role(0, 3) == ColourRole::monitor);
    CHECK(overlay_role(1, 3) == ColourRole::inbetween);
    CHECK(overlay_role(2, 3) == ColourRole::key_frame);
    const GraphicsScreen screen = three_levels_overlay();
    for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille, GlyphSet::blocks}) {
        CAPTURE(static_cast<int>(glyphs));
        const CellGrid grid = render_screen_cells(screen, {80, short_screen_rows}, glyphs);
        for (const ColourRole role : {ColourRole::monitor, ColourRole::inbetween, ColourRole::key_frame}) {
            CAPTURE(colour_role_name(role));
            int cells = 0;
            // Inside the boundary (the short screen's drawing area is rows 0-16).
            for (int row = 1; row < layout::message_row - 2; ++row)
                for (int column = 1; column < 79; ++column)
                    cells += grid.role_at(column, row) == role && grid.at(column, row) != U' ' &&
                             grid.at(column, row) != U'\u2800';
            CHECK(cells >= 12);
        }
    }
}

TEST_CASE("overlay legends: a fit's keys and in-betweens, a scene's frame numbers, fewer parts for fewer items",
          "[session][overlay]")
{
    CHECK(overlay_legend(key_frames_names("k1.dat", "k2.dat", 14), 14) ==
          "solid: KEY1 k1.dat  dashed: KEY2 k2.dat  dotted: 12 in-betweens");
    CHECK(overlay_legend(scene_frames_names(73), 73) == "solid: frame 0  dashed: frame 72  dotted: frames 1-71");
    CHECK(overlay_legend(scene_frames_names(3), 3) == "solid: frame 0  dashed: frame 2  dotted: frame 1");
    CHECK(overlay_legend(scene_frames_names(2), 2) == "solid: frame 0  dashed: frame 1");
    CHECK(overlay_legend(scene_frames_names(1), 1) == "solid: frame 0");
    CHECK(overlay_legend(scene_frames_names(0), 0).empty());
    CHECK(overlay_style(0, 5) == LineStyle::solid);
    CHECK(overlay_style(1, 5) == LineStyle::dotted);
    CHECK(overlay_style(3, 5) == LineStyle::dotted);
    CHECK(overlay_style(4, 5) == LineStyle::dashed);
    CHECK(overlay_style(0, 1) == LineStyle::solid);
}

TEST_CASE("an overlay's SVG dashes and dots are the PNG's: the same pattern and phase, run for run", "[session][overlay][svg]")
{
    const FrameSequence frames = three_levels();
    const GraphicsScreen screen = three_levels_overlay();
    const std::string svg = encode_svg(screen);
    // The SVG draws the dashes as the pieces the Painter lit (no stroke-dasharray, which viewers
    // would phase each in their own way): each dash and each dot is the PNG's, where the PNG has it.
    CHECK(svg.find("stroke-dasharray") == std::string::npos);
    const auto dashed = svg_runs(path_data_of_class(svg, "dashed clipped"));
    const auto dotted = svg_runs(path_data_of_class(svg, "dotted clipped"));
    CHECK(dashed == bitmap_runs(screen.bitmap, row_of(frames, 2)));
    CHECK(dotted == bitmap_runs(screen.bitmap, row_of(frames, 1)));
    REQUIRE(dashed.size() > 10);
    for (std::size_t k = 0; k + 1 < dashed.size(); ++k)
        CHECK(dashed[k].second - dashed[k].first + 1 == 6);
    CHECK(dashed.back().second - dashed.back().first + 1 <= 6);
    for (const auto& [first, last] : dotted)
        CHECK(first == last);
}

TEST_CASE("the session's last screen is the overlay the pictures draw, with the same legend", "[session][overlay]")
{
    UnloggedSteps log;
    AnimationPlayer player(three_levels(), one_line(), {"key1.dat", "key2.dat"}, face_on, 100, log);
    while (player.playing())
        player.tick();
    player.update(command::Continue{}); // any key after the last frame (key map: Continue)
    const GraphicsScreen screen = player.view();
    const GraphicsScreen picture = three_levels_overlay();
    CHECK(screen.bitmap == picture.bitmap);
    REQUIRE(screen.text.size() == 4); // the caption, the legend's three parts
    CHECK(legend_of(screen) == legend_of(picture));
}

TEST_CASE("lettered points are marked with an x and lettered in the cell under them", "[session][overlay]")
{
    const FrameSequence frames = three_levels();
    const FramesOverlay overlay{scene_frames_names(3), {{"A", {0, 0, 0}}, {"B", {0, 20, 10}}}, {"A-B: the ends"}, false, {}};
    const GraphicsScreen screen = frames_overlay_screen(frames, one_line(), face_on, "caption", overlay);
    const ViewTransform view = frames_view(frames, face_on);
    REQUIRE(screen.marks.size() == 2);
    REQUIRE(screen.text.size() == 7); // two letters, the caption, the legend's three parts, the note
    for (std::size_t k = 0; k < 2; ++k) {
        const PixelPoint at = view.to_device(overlay.points[k].position).rounded();
        CHECK(screen.marks[k].at == at);
        CHECK(screen.marks[k].kind == MarkKind::control_point);
        const TextLine& letter = screen.text[k];
        CHECK(letter.text == overlay.points[k].label);
        CHECK(letter.column == at.x / hercules::cell_width);
        const int top = hercules::text_row_top(letter.row);
        CHECK(top > at.y + 2);
        CHECK(top <= at.y + 2 + hercules::text_row_top(1) + 1);
    }
    CHECK(screen.text[6].row == overlay_legend_row + 1);
    CHECK(screen.text[6].text == "A-B: the ends");
}

TEST_CASE("on the terminal the overlay draws the first, middle and last frames and says so, pictures every frame",
          "[session][overlay]")
{
    FrameSequence frames(5, 2);
    for (std::size_t k = 0; k < 5; ++k) {
        const double z = 10.0 - 2.5 * static_cast<double>(k);
        frames.frame(k)[0] = {0, 0, z};
        frames.frame(k)[1] = {0, 20, z};
    }
    REQUIRE(overlaid_frames(5, true) == std::vector<std::size_t>{0, 2, 4});
    REQUIRE(overlaid_frames(3, true) == std::vector<std::size_t>{0, 1, 2});
    REQUIRE(overlaid_frames(4, false) == std::vector<std::size_t>{0, 1, 2, 3});
    UnloggedSteps log;
    AnimationPlayer player(frames, one_line(), {"key1.dat", "key2.dat"}, face_on, 100, log);
    while (player.playing())
        player.tick();
    player.update(command::Continue{});
    REQUIRE(player.leaf() == AnimationPlayer::State::overlaid);
    const GraphicsScreen screen = player.view();
    const GraphicsScreen picture = player.picture();
    REQUIRE(picture.bitmap == player.overlay_picture().bitmap);
    for (std::size_t k = 0; k < 5; ++k) {
        const Row row = row_of(frames, k);
        INFO("frame " << k);
        CHECK(lit_along(picture.bitmap, row).size() > 10);
        CHECK(lit_along(screen.bitmap, row).empty() == (k == 1 || k == 3));
    }
    REQUIRE(screen.text.size() == 5);
    CHECK(legend_of(screen) == "solid: KEY1 key1.dat  dashed: KEY2 key2.dat  dotted: in-between 2 (inb002.dat)");
    CHECK(screen.text[4].text == "the first, middle and last of 5 frames (pictures, --png, draw every frame)");
    CHECK(legend_of(picture) == "solid: KEY1 key1.dat  dashed: KEY2 key2.dat  dotted: 3 in-betweens");
}
