#include "apcs/screens/figures.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <climits>
#include <vector>

using namespace apcs;

namespace {

struct LitBox {
    int left = INT_MAX, top = INT_MAX, right = INT_MIN, bottom = INT_MIN;
};

LitBox lit_box(const Bitmap& bitmap)
{
    LitBox box;
    for (int y = 0; y < bitmap.height(); ++y)
        for (int x = 0; x < bitmap.width(); ++x)
            if (bitmap.get(x, y)) {
                box.left = std::min(box.left, x);
                box.right = std::max(box.right, x);
                box.top = std::min(box.top, y);
                box.bottom = std::max(box.bottom, y);
            }
    return box;
}

bool box_outline_lit(const Bitmap& bitmap, PixelPoint centre)
{
    for (int d = -4; d <= 4; ++d)
        if (!bitmap.get(centre.x + d, centre.y - 4) || !bitmap.get(centre.x + d, centre.y + 4) ||
            !bitmap.get(centre.x - 4, centre.y + d) || !bitmap.get(centre.x + 4, centre.y + d))
            return false;
    return true;
}

} // namespace

TEST_CASE("a marked frame figure boxes each key point, letters it and explains it under the drawing", "[figures]")
{
    // A closed square in the y-z plane, seen face-on: its four corners are the drawing's extremes.
    const std::vector<Vec3> points{{0, 0, 0}, {0, 10, 0}, {0, 10, 10}, {0, 0, 10}};
    const Graphic square{{{"square", Closure::closed, points}}};
    const GraphicsScreen plain = draw_marked_frame_figure("Fig. X", points, square, {0, 90}, {});
    const LitBox corners = lit_box(plain.bitmap);
    REQUIRE(corners.right - corners.left > 100);

    const FigureMark mark{"A", points[2], "the corner y = 10, z = 10"};
    const GraphicsScreen marked = draw_marked_frame_figure("Fig. X", points, square, {0, 90}, {&mark, 1});
    // Face-on, z is up and y to the right: (0, 10, 10) is the top right corner.
    const PixelPoint corner{corners.right, corners.top};
    CHECK_FALSE(box_outline_lit(plain.bitmap, corner));
    CHECK(box_outline_lit(marked.bitmap, corner));
    // The letter: lit pixels right of the box and above it, where the plain figure has none.
    int letter_pixels = 0;
    for (int y = corner.y - 16; y < corner.y - 2; ++y)
        for (int x = corner.x + 7; x < corner.x + 16; ++x)
            letter_pixels += marked.bitmap.get(x, y) && !plain.bitmap.get(x, y) ? 1 : 0;
    CHECK(letter_pixels >= 10);
    const bool explained = std::any_of(marked.text.begin(), marked.text.end(), [](const TextLine& line) {
        return line.row == 22 && line.text == "A  the corner y = 10, z = 10";
    });
    CHECK(explained);
    CHECK(marked.text.size() == plain.text.size() + 1);
}
