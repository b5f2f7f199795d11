#include "apcs/raster/gif_encoder.h"

#include "support/gif_frames.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace apcs;

TEST_CASE("a GIF delay is the --delay in hundredths of a second, rounded, at least 1", "[raster][gif]")
{
    CHECK(gif_delay_centiseconds(200) == 20);
    CHECK(gif_delay_centiseconds(15) == 2);
    CHECK(gif_delay_centiseconds(14) == 1);
    CHECK(gif_delay_centiseconds(4) == 1);
    CHECK(gif_delay_centiseconds(1) == 1);
}

TEST_CASE("an animated GIF holds each frame at 720x522, rows 1.5 tall, white on black, looping", "[raster][gif]")
{
    std::vector<Bitmap> bitmaps(3);
    bitmaps[0].set(10, 0, true);  // picture rows 0 and 1
    bitmaps[1].set(20, 1, true);  // picture row 2
    bitmaps[2].set(719, 347, true); // picture row 521
    std::size_t next = 0;
    const auto gif = encode_gif(
        bitmaps.size(),
        [&](std::size_t k) {
            REQUIRE(k == next++);
            return bitmaps[k];
        },
        7);
    REQUIRE(gif);
    const auto read = test::read_gif(*gif);
    REQUIRE(read);
    CHECK(read->width == 720);
    CHECK(read->height == 522);
    CHECK(read->loops);
    REQUIRE(read->palette.size() == 2);
    CHECK(read->palette[0].Red == 0);
    CHECK(read->palette[1].Red == 255);
    REQUIRE(read->frames.size() == 3);
    for (const auto& frame : read->frames) {
        CHECK(frame.width == 720);
        CHECK(frame.height == 522);
        CHECK(frame.delay_centiseconds == 7);
    }
    const auto lit = [&](std::size_t k, int x, int row) { return read->frames[k].pixels[static_cast<std::size_t>(row * 720 + x)] == 1; };
    CHECK(lit(0, 10, 0));
    CHECK(lit(0, 10, 1));
    CHECK_FALSE(lit(0, 10, 2));
    CHECK(lit(1, 20, 2));
    CHECK_FALSE(lit(1, 20, 1));
    CHECK(lit(2, 719, 521));
    CHECK_FALSE(lit(2, 719, 520));
    CHECK_FALSE(lit(2, 10, 0));
}

TEST_CASE("a GIF of no frames is refused with the reason", "[raster][gif]")
{
    const auto gif = encode_gif(0, [](std::size_t) { return Bitmap(720, 348); }, 20);
    REQUIRE_FALSE(gif);
    REQUIRE(gif.error().message == "there are no frames");
}
