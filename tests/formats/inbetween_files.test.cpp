#include "apcs/formats/inbetween_files.h"

#include "apcs/animation/vector_inbetween.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <string>
#include <vector>

using namespace apcs;
using test::read_all;
using test::TempFolder;

namespace {

// Frames 0 … 4 of one point moving from (0, 0, 0) to (4, 0, 0): in-betweens at x = 1, 2, 3.
FrameSequence four_steps()
{
    const std::array<Vec3, 1> begin{{{0, 0, 0}}};
    const std::array<Vec3, 1> end{{{4, 0, 0}}};
    return interpolate_frames(begin, end, 4, SpeedLaw::linear);
}

Graphic one_point()
{
    Graphic structure;
    structure.parts.push_back({"", Closure::open, {{0, 0, 0}}});
    return structure;
}

} // namespace

TEST_CASE("the in-betweens are written as inb001.dat … and returned in order", "[formats][inbetween-files]")
{
    const TempFolder folder;
    const auto written = write_inbetween_files(four_steps(), one_point(), folder.path(), KeyFileGuard{});
    REQUIRE(written.has_value());
    REQUIRE(*written == std::vector<std::filesystem::path>{folder / "inb001.dat", folder / "inb002.dat", folder / "inb003.dat"});
    // The keys' largest coordinate is 4: 9 − ⌊log10 4⌋ = 9 decimals.
    REQUIRE(read_all(folder / "inb002.dat") == "; APCS in-between 2 of 3\n2.000000000 0.000000000 0.000000000\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "inb004.dat"));
}

TEST_CASE("a key file among the targets stops the writing before any file is written", "[formats][inbetween-files]")
{
    const TempFolder folder;
    const std::filesystem::path key = folder.write("INB003.DAT", "9 9\n8 8\n");
    KeyFileGuard guard;
    guard.protect(key);
    const auto written = write_inbetween_files(four_steps(), one_point(), folder.path(), guard);
    REQUIRE_FALSE(written.has_value());
    REQUIRE(written.error().to_string() == (folder / "inb003.dat").string() + ": is a key file; key files are never written");
    REQUIRE_FALSE(std::filesystem::exists(folder / "inb001.dat"));
    REQUIRE(read_all(key) == "9 9\n8 8\n");
}

TEST_CASE("in-betweens into a missing folder make it, one level only — a file of its name is refused",
          "[formats][inbetween-files]")
{
    const TempFolder folder;
    const auto made = write_inbetween_files(four_steps(), one_point(), folder / "new/", KeyFileGuard{});
    REQUIRE(made.has_value());
    REQUIRE(read_all(folder / "new" / "inb001.dat").size() > 0);

    const auto nested = write_inbetween_files(four_steps(), one_point(), folder / "none" / "new", KeyFileGuard{});
    REQUIRE_FALSE(nested.has_value());
    REQUIRE(nested.error().to_string() == (folder / "none" / "new").string() + ": cannot be made: " +
                                              (folder / "none").string() +
                                              " is not a folder (--out makes one level, not its parents)");
    REQUIRE_FALSE(std::filesystem::exists(folder / "none"));

    folder.write("plain", "text\n");
    const auto over_file = write_inbetween_files(four_steps(), one_point(), folder / "plain", KeyFileGuard{});
    REQUIRE_FALSE(over_file.has_value());
    REQUIRE(over_file.error().message == "is not a folder; expected a folder for the in-between files");
    REQUIRE(read_all(folder / "plain") == "text\n");
}

TEST_CASE("in-between files numbered above this run's are found in number order and named in one note",
          "[formats][inbetween-files]")
{
    const std::vector<std::string> names{"inb020.dat", "INB013.DAT", "inb012.dat", "inb1000.dat", "inb14.dat",
                                         "inbx13.dat", "key1.dat", "inb015.dat.bak"};
    const std::vector<std::string> earlier = inbetweens_beyond(names, 12);
    REQUIRE(earlier == std::vector<std::string>{"INB013.DAT", "inb020.dat", "inb1000.dat"});
    REQUIRE(earlier_inbetweens_note(earlier) == "INB013.DAT to inb1000.dat (3 files) are from an earlier run (not rewritten)");
    REQUIRE(earlier_inbetweens_note(std::vector<std::string>{"inb013.dat"}) ==
            "inb013.dat is from an earlier run (not rewritten)");
    REQUIRE_FALSE(earlier_inbetweens_note(inbetweens_beyond(names, 1000)).has_value());

    const TempFolder folder;
    folder.write("inb004.dat", "0 0\n");
    folder.write("inb003.dat", "0 0\n");
    REQUIRE(inbetweens_beyond(folder.path(), 3) == std::vector<std::string>{"inb004.dat"});
}

TEST_CASE("streamed in-betweens are byte for byte the files of the whole frames, across chunks and parts",
          "[formats][inbetween-files]")
{
    // Three parts of 5000, 3000 and 2001 points (the chunks are 4096): PART lines, and chunks that
    // end inside a part and at its end.
    Graphic structure;
    std::vector<Vec3> key1;
    std::vector<Vec3> key2;
    for (const auto& [name, count] : {std::pair{"a", 5000}, std::pair{"b", 3000}, std::pair{"c", 2001}}) {
        GraphicPart part{name, Closure::open, {}};
        for (int i = 0; i < count; ++i) {
            const double t = static_cast<double>(key1.size()) / 10001.0;
            key1.push_back({0, 10 * t, std::sin(20 * t)});
            key2.push_back({8, 10 * t + 1, std::cos(20 * t)});
            part.points.push_back(key1.back());
        }
        structure.parts.push_back(std::move(part));
    }
    EdgePath first;
    EdgePath last;
    for (int k = 0; k <= 5; ++k) {
        const double w = k / 5.0;
        first.positions.push_back(lerp(key1.front(), key2.front(), w) + Vec3{0, 0, std::sin(w * 3.14159)});
        first.progress.push_back(w);
        last.positions.push_back(lerp(key1.back(), key2.back(), w * w));
        last.progress.push_back(w * w);
    }
    first.positions.front() = key1.front();
    first.positions.back() = key2.front();
    last.positions.front() = key1.back();
    last.positions.back() = key2.back();
    const SurfaceFitter fitter(key1, key2, Closure::open, first, last);
    const FrameSequence frames = fit_surface(key1, key2, Closure::open, first, last);

    const TempFolder streamed;
    const TempFolder whole;
    REQUIRE(write_inbetween_files(fitter, structure, streamed.path(), KeyFileGuard{})->size() == 4);
    REQUIRE(write_inbetween_files(frames, structure, whole.path(), KeyFileGuard{})->size() == 4);
    for (const char* name : {"inb001.dat", "inb002.dat", "inb003.dat", "inb004.dat"}) {
        CAPTURE(name);
        const std::string text = read_all(streamed / name);
        REQUIRE(text == read_all(whole / name));
        REQUIRE(std::count(text.begin(), text.end(), '\n') == 1 + 3 + 10001); // heading, PART lines, points
    }
}
