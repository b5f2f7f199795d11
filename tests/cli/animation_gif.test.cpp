#include "support/gif_frames.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using apcs::test::read_gif;
using apcs::test::run_apcs;
using apcs::test::TempFolder;

namespace {

std::string example(const std::string& name)
{
    return (std::filesystem::path(APCS_SOURCE_DIR) / "data" / "n-to-l" / name).string();
}

std::string file_text(const std::filesystem::path& file)
{
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// How many pixels of the frame are lit.
std::size_t lit_count(const apcs::test::GifFrames::Frame& frame)
{
    std::size_t count = 0;
    for (const unsigned char pixel : frame.pixels)
        count += pixel == 1 ? 1 : 0;
    return count;
}

} // namespace

TEST_CASE("apcs fit --gif writes M+2 frames of 720x522 at the delay, looping", "[cli][gif]")
{
    const TempFolder folder;
    const auto result = run_apcs({"fit", example("key1.dat"), example("key2.dat"), example("way1.dat"),
                                  example("way4.dat"), "--inbetweens", "5", "--delay", "125", "--gif",
                                  (folder / "fit.gif").string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    const auto gif = read_gif(file_text(folder / "fit.gif"));
    REQUIRE(gif);
    CHECK(gif->loops);
    REQUIRE(gif->frames.size() == 7);
    for (const auto& frame : gif->frames) {
        CHECK(frame.width == 720);
        CHECK(frame.height == 522);
        CHECK(frame.delay_centiseconds == 13);
    }
    // One frame each, not the overlay: the frames differ from one another.
    CHECK(gif->frames[0].pixels != gif->frames[6].pixels);
    CHECK(gif->frames[0].pixels != gif->frames[3].pixels);
    CHECK(lit_count(gif->frames[3]) > 0);
    CHECK_FALSE(std::filesystem::exists(folder / "inb001.dat"));
}

TEST_CASE("apcs inbetween --gif writes T+1 frames — --gif - writes them to standard output", "[cli][gif]")
{
    const auto result = run_apcs({"inbetween", example("key1.dat"), example("key2.dat"), "--frames", "4", "--gif", "-"});
    REQUIRE(result.status == 0);
    const auto gif = read_gif(result.out);
    REQUIRE(gif);
    CHECK(gif->frames.size() == 5);
    CHECK(gif->frames.at(0).delay_centiseconds == 20);
}

TEST_CASE("a --gif name that does not end in .gif is exit 2 — --gif is not an option of path or draw", "[cli][gif]")
{
    for (const std::vector<std::string>& usage :
         {std::vector<std::string>{"inbetween", example("key1.dat"), example("key2.dat"), "--gif", "x.png"},
          std::vector<std::string>{"fit", "a", "b", "c", "d", "--gif", "x.svg"},
          std::vector<std::string>{"path", example("way1.dat"), "--gif", "x.gif"},
          std::vector<std::string>{"draw", example("key1.dat"), "--gif", "x.gif"},
          std::vector<std::string>{"inbetween", example("key1.dat"), example("key2.dat"), "--gif", "-", "--print"}}) {
        INFO(usage.front() << " " << usage.back());
        const auto result = run_apcs(usage);
        CHECK(result.status == 2);
        CHECK(result.out.empty());
    }
    CHECK(run_apcs({"inbetween", example("key1.dat"), example("key2.dat"), "--gif", "x.png"})
              .err.find("a GIF file's name ends in .gif, found 'x.png'") != std::string::npos);
}

TEST_CASE("a scene of groups only plays its frames in a GIF, each empty but for the message line", "[cli][gif]")
{
    // Its objects have no drawing: frames of no points, which still count (the GIF had 0 frames
    // and the command said only "cannot encode the GIF image").
    const TempFolder folder;
    const auto scene = folder.write("groups.scn", "FRAMES 3\nOBJECT g\nOBJECT h PARENT g\n");
    const auto result = run_apcs({"play", scene.string(), "--gif", (folder / "groups.gif").string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.err.empty());
    const auto gif = read_gif(file_text(folder / "groups.gif"));
    REQUIRE(gif);
    REQUIRE(gif->frames.size() == 4);
}
