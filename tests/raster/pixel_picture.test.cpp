#include "apcs/raster/pixel_picture.h"

#include <catch2/catch.hpp>

using namespace apcs;

// The drawing area of the session's graphics screens: raster rows 0-260 (layout::drawing_area and
// the row under its boundary), text rows 0-17 at 80x24.
constexpr int drawing_rows = 261;

TEST_CASE("the drawing area's raster rows are 18 cell rows of 24, 36 of 48", "[raster][pixels]")
{
    CHECK(cell_rows_above(260, 348, {80, 24}) == 18);
    CHECK(cell_rows_above(261, 348, {80, 24}) == 18);
    CHECK(cell_rows_above(262, 348, {80, 24}) == 19);
    CHECK(cell_rows_above(260, 348, {160, 48}) == 36);
    CHECK(cell_rows_above(348, 348, {80, 24}) == 24);
    CHECK(cell_rows_above(0, 348, {80, 24}) == 0);
}

TEST_CASE("xterm's 9x15 cells at 80x24: the height limits the scale, the picture is centred in whole cells",
          "[raster][pixels]")
{
    const std::optional<PicturePlacement> placement = place_picture({80, 24}, 18, 720, drawing_rows, {9, 15});
    REQUIRE(placement);
    // 18 rows of 15 pixels = 270; the raster's 261 rows at 1.5 are 391.5 tall: scale 270/391.5,
    // so 720 becomes 496 (rounded down).
    CHECK(placement->content_height == 270);
    CHECK(placement->content_width == 496);
    CHECK(placement->columns == 56);
    CHECK(placement->rows == 18);
    CHECK(placement->column == 12);
    CHECK(placement->pixel_width() == 504);
    CHECK(placement->pixel_height() == 270);
}

TEST_CASE("cells three times as tall as wide: the width limits the scale and the picture takes fewer rows",
          "[raster][pixels]")
{
    const std::optional<PicturePlacement> placement = place_picture({80, 24}, 18, 720, drawing_rows, {6, 30});
    REQUIRE(placement);
    // 80 columns of 6 = 480 pixels across: scale 480/720, so 391.5 becomes 261.
    CHECK(placement->content_width == 480);
    CHECK(placement->content_height == 261);
    CHECK(placement->columns == 80);
    CHECK(placement->column == 0);
    CHECK(placement->rows == 9);
}

TEST_CASE("no cell size, no area or no raster rows: no placement", "[raster][pixels]")
{
    CHECK_FALSE(place_picture({80, 24}, 18, 720, drawing_rows, {0, 15}));
    CHECK_FALSE(place_picture({80, 24}, 18, 720, drawing_rows, {9, 0}));
    CHECK_FALSE(place_picture({0, 0}, 18, 720, drawing_rows, {9, 15}));
    CHECK_FALSE(place_picture({80, 24}, 0, 720, drawing_rows, {9, 15}));
    CHECK_FALSE(place_picture({80, 24}, 18, 720, 0, {9, 15}));
}

TEST_CASE("a reduced picture keeps one-pixel lines (max pooling) and is dark outside the raster", "[raster][pixels]")
{
    Bitmap raster;
    for (int x = 0; x < raster.width(); ++x)
        raster.set(x, 101, true); // a one-pixel horizontal line
    for (int y = 0; y < drawing_rows; ++y)
        raster.set(719, y, true); // the boundary's right line
    raster.set(300, 300, true);   // below the drawing area: not in the picture
    const PicturePlacement placement = *place_picture({80, 24}, 18, 720, drawing_rows, {9, 15});
    const Bitmap picture = scale_to_picture(raster, placement);
    REQUIRE(picture.width() == 504);
    REQUIRE(picture.height() == 270);
    // Picture row y pools raster rows floor(y·261/270) up to floor((y+1)·261/270): row 101 is
    // row 105's alone.
    int lit_in_row = 0;
    for (int x = 0; x < placement.content_width; ++x)
        lit_in_row += picture.get(x, 105) ? 1 : 0;
    CHECK(lit_in_row == placement.content_width);
    for (int y = 0; y < placement.content_height; ++y)
        REQUIRE(picture.get(placement.content_width - 1, y));
    // Right of the content: black padding to the whole cell.
    for (int y = 0; y < picture.height(); ++y)
        for (int x = placement.content_width; x < picture.width(); ++x)
            REQUIRE_FALSE(picture.get(x, y));
    // The horizontal line and the right line only, each one pixel thick.
    CHECK(picture.lit_count() == static_cast<std::size_t>(placement.content_width + placement.content_height - 1));
}

TEST_CASE("an enlarged picture repeats each raster pixel over the screen pixels it covers", "[raster][pixels]")
{
    Bitmap raster(4, 2);
    raster.set(1, 0, true);
    PicturePlacement placement;
    placement.columns = 1;
    placement.rows = 1;
    placement.cell = {8, 6};
    placement.raster_rows = 2;
    placement.content_width = 8; // x2
    placement.content_height = 6; // x3 (each raster row 1.5 times as tall, then x2)
    const Bitmap picture = scale_to_picture(raster, placement);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x)
            REQUIRE(picture.get(x, y) == (y < 3 && (x == 2 || x == 3)));
}

TEST_CASE("the changed band is the whole cell rows around the rows that differ", "[raster][pixels]")
{
    const Bitmap sent(27, 60);
    CHECK_FALSE(changed_band(sent, sent, 15));
    Bitmap now = sent;
    now.set(5, 20, true);
    CHECK(changed_band(sent, now, 15) == CellRowBand{1, 2});
    now.set(26, 14, true);
    now.set(0, 31, true);
    CHECK(changed_band(sent, now, 15) == CellRowBand{0, 3});
    Bitmap last = sent;
    last.set(0, 59, true);
    CHECK(changed_band(sent, last, 15) == CellRowBand{3, 4});
}

TEST_CASE("a picture of another size is changed as a whole", "[raster][pixels]")
{
    CHECK(changed_band(Bitmap(27, 60), Bitmap(27, 45), 15) == CellRowBand{0, 3});
    CHECK(changed_band(Bitmap(27, 60), Bitmap(18, 60), 15) == CellRowBand{0, 4});
    CHECK_FALSE(changed_band(Bitmap(27, 60), Bitmap(27, 60), 0));
}

TEST_CASE("a limit on the picture (xterm: 1000 pixels across) makes it smaller, in whole cells within it",
          "[raster][pixels]")
{
    // 170 columns of 9: unlimited, the height limits the scale and the picture is 1,053 pixels
    // across, which xterm (1000x1000 at most) would not show at all.
    const std::optional<PicturePlacement> unlimited = place_picture({170, 51}, 38, 720, drawing_rows, {9, 15});
    REQUIRE(unlimited);
    CHECK(unlimited->content_width == 1048);
    CHECK(unlimited->pixel_width() == 1053);
    const std::optional<PicturePlacement> limited =
        place_picture({170, 51}, 38, 720, drawing_rows, {9, 15}, PictureLimit{1000, 825});
    REQUIRE(limited);
    // 111 cells of 9 = 999 across limit the scale: 261 rows at 1.5 become 543.
    CHECK(limited->content_width == 999);
    CHECK(limited->content_height == 543);
    CHECK(limited->columns == 111);
    CHECK(limited->rows == 37);
    CHECK(limited->column == 29);
    // Its sixel bands, rounded up to 6 rows, stay within the limit's height too.
    const std::optional<PicturePlacement> low =
        place_picture({170, 51}, 38, 720, drawing_rows, {9, 15}, PictureLimit{1000, 300});
    REQUIRE(low);
    CHECK(low->pixel_height() + 5 <= 300);
    CHECK(low->pixel_width() <= 1000);
    // A limit under a cell leaves no picture.
    CHECK_FALSE(place_picture({80, 24}, 18, 720, drawing_rows, {9, 15}, PictureLimit{8, 300}));
    CHECK_FALSE(place_picture({80, 24}, 18, 720, drawing_rows, {9, 15}, PictureLimit{720, 19}));
}
