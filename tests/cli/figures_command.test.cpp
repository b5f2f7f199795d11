#include "support/golden.h"
#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <png.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

using namespace apcs;

namespace {

// The pixels of a PNG file (8-bit grey), or empty when it cannot be read.
std::vector<png_byte> grey_pixels(const std::string& bytes, png_uint_32& width, png_uint_32& height)
{
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()) == 0)
        return {};
    image.format = PNG_FORMAT_GRAY;
    std::vector<png_byte> pixels(PNG_IMAGE_SIZE(image));
    width = image.width;
    height = image.height;
    if (png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr) == 0)
        return {};
    return pixels;
}

} // namespace

TEST_CASE("apcs figures draws the thesis' figures and the examples as approved rasters", "[cli][figures]")
{
    const test::TempFolder folder;
    const auto result = test::run_apcs({"figures", "--out", folder.path().string()});
    REQUIRE(result.status == 0);
    const std::vector<std::string> names{"fig-3-1-1.png",          "fig-3-1-2.png",          "fig-3-1-3.png",
                                         "fig-3-1-4.png",          "example-1-n-to-l-a.png", "example-1-n-to-l-b.png",
                                         "example-2-stick-a.png",  "example-2-stick-b.png",  "example-3-snake-apple.png"};
    for (const std::string& name : names) {
        CAPTURE(name);
        const std::string written = test::read_all(folder / name);
        png_uint_32 width = 0;
        png_uint_32 height = 0;
        const std::vector<png_byte> pixels = grey_pixels(written, width, height);
        REQUIRE(width == 720);
        REQUIRE(height == 348);
        // Golden rasters are compared pixel by pixel, not byte by byte, so that another zlib may
        // compress them differently.
        const std::filesystem::path golden = std::filesystem::path(APCS_SOURCE_DIR) / "tests/golden/figures" / name;
        if (std::getenv("APCS_APPROVE") != nullptr) {
            std::filesystem::create_directories(golden.parent_path());
            std::ofstream(golden, std::ios::binary) << written;
            continue;
        }
        png_uint_32 golden_width = 0;
        png_uint_32 golden_height = 0;
        REQUIRE(grey_pixels(test::read_all(golden), golden_width, golden_height) == pixels);
    }
}

TEST_CASE("apcs figures into a missing folder is exit 1", "[cli][figures]")
{
    const test::TempFolder folder;
    const auto result = test::run_apcs({"figures", "--out", (folder / "none").string()});
    REQUIRE(result.status == 1);
    REQUIRE(result.err.find("is not a folder") != std::string::npos);
}

TEST_CASE("each example's session replays headless to its approved in-between files", "[session][examples]")
{
    for (const std::string example : {"n-to-l", "stick", "snake-apple"}) {
        const test::TempFolder folder;
        for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "data" / example))
            std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
        const auto result = test::run_apcs({"--keys", (folder / "session.keys").string(), "--workdir", folder.path().string()});
        CAPTURE(example);
        REQUIRE(result.status == 0);
        REQUIRE(result.err.empty());
        for (int k = 1; k <= 12; ++k) {
            char name[16];
            std::snprintf(name, sizeof name, "inb%03d.dat", k);
            test::check_golden("examples/" + example + "/" + name, test::read_all(folder / name));
        }
    }
}
