#include "apcs/cli/export_command.h"

#include "support/run_apcs.h"
#include "support/small_example.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace apcs;
using test::run_apcs;
using test::TempFolder;

namespace {

std::string text_of(const std::filesystem::path& file)
{
    std::ostringstream text;
    text << std::ifstream(file, std::ios::binary).rdbuf();
    return text.str();
}

std::size_t count_of(const std::string& text, const std::string& what)
{
    std::size_t count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++count;
    return count;
}

} // namespace

TEST_CASE("apcs export FILE.dat --sif: a TCB waypoint per control point, 2-D data seen from the top", "[cli][sif]")
{
    const TempFolder folder;
    // z all 0: the top view, (x, y) as they are; t c b of the file's own columns.
    const auto flat = folder.write("flat.dat", "0 0 0 0.5 0 0 0\n4 2 0 0 -0.25 0 0\n8 -2 0 0 0 0.75 0\n");
    const auto result = run_apcs({"export", flat.string(), "--sif", (folder / "flat.sif").string(), "--fps", "30"});
    REQUIRE(result.status == 0);
    CHECK(result.err.empty());
    const std::string document = text_of(folder / "flat.sif");
    CHECK(count_of(document, "<waypoint ") == 3);
    CHECK(document.find("<waypoint time=\"12f\" before=\"auto\" after=\"auto\" tension=\"0\" continuity=\"-0.25\"") !=
          std::string::npos);
    // The waypoints' coordinates are exact, in their shortest form.
    CHECK(document.find("<vector><x>4</x><y>2</y></vector></waypoint>") != std::string::npos);
    CHECK(document.find("fps=\"30\"") != std::string::npos);
}

TEST_CASE("apcs export names what TCB leaves out on stderr, and --sif-motion frames keeps it", "[cli][sif]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const std::string way1 = (folder / "way1.dat").string();
    const auto tcb = run_apcs({"export", way1, "--sif", "-", "--slopes", "0.5", "1", "--accel", "0.3"});
    REQUIRE(tcb.status == 0);
    CHECK(tcb.err.find(way1 + ": not carried to Synfig: the end slopes 0.5 1") != std::string::npos);
    CHECK(tcb.err.find("not carried to Synfig: the acceleration 0.3 of the span from control point 1 to 3") !=
          std::string::npos);
    CHECK(tcb.out.starts_with("<?xml"));
    CHECK(tcb.out.find("<!-- Not carried by Synfig's TCB waypoints") != std::string::npos);

    const auto frames = run_apcs({"export", way1, "--sif", "-", "--sif-motion", "frames", "--accel", "0.3",
                                  "--inbetweens", "5"});
    REQUIRE(frames.status == 0);
    CHECK(frames.err.empty());
    // KEY1, 5 in-betweens, KEY2: 7 linear waypoints, frames 0 to 6.
    CHECK(count_of(frames.out, "before=\"linear\" after=\"linear\"") == 7);
    CHECK(frames.out.find("end-time=\"6f\"") != std::string::npos);
}

TEST_CASE("apcs export with fit's four files: every part's vertices move through every frame", "[cli][sif]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const auto result = run_apcs({"export", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                                  (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--sif",
                                  (folder / "n.sif").string(), "--inbetweens", "3"});
    REQUIRE(result.status == 0);
    const std::string document = text_of(folder / "n.sif");
    // One open part of 4 points (KEY2 gains one), 5 frames: 20 waypoints, frames 0 … 4.
    CHECK(count_of(document, "<layer type=\"outline\"") == 1);
    CHECK(count_of(document, "<waypoint ") == 20);
    CHECK(document.find("end-time=\"4f\"") != std::string::npos);
}

TEST_CASE("apcs export refuses: wrong file counts, no --sif, an input as the document", "[cli][sif]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const std::string way1 = (folder / "way1.dat").string();
    const auto two = run_apcs({"export", way1, way1, "--sif", (folder / "x.sif").string()});
    CHECK(two.status == 2);
    CHECK(two.err.find("takes one path file, or four files KEY1 KEY2 PATH_FIRST PATH_LAST; 2 given") !=
          std::string::npos);
    const auto no_sif = run_apcs({"export", way1});
    CHECK(no_sif.status == 2);
    CHECK(no_sif.err.find("--sif is required") != std::string::npos);
    const std::string before = text_of(folder / "way1.dat");
    const auto over_input = run_apcs({"export", way1, "--sif", way1});
    CHECK(over_input.status == 1);
    CHECK(over_input.err.find("is an input of this run; --sif never writes over an input") != std::string::npos);
    CHECK(text_of(folder / "way1.dat") == before);
    CHECK_FALSE(std::filesystem::exists(folder / "way1.bak"));
    const auto span = run_apcs({"export", way1, "--sif", "-", "--frames-per-span", "10001"});
    CHECK(span.status == 2);
}

TEST_CASE("apcs path FILE.sif reads an exported path back: the same --print in each named view's plane", "[cli][sif]")
{
    const TempFolder folder;
    struct Case {
        const char* view;
        const char* points; // in the view's plane
    };
    for (const Case& each : {Case{"top", "0 0 0 0.5 0 0 0\n2 3 0 -0.5 0.3 0.2 0\n5 1 0 0 -0.5 0.5 0\n9 0 0 0 0 0 0\n"},
                             Case{"front", "0 0 0 0.2 0 0 0\n0 3 4 0 0.4 0 0\n0 5 0 0 0 -0.3 0\n"},
                             Case{"side", "0 0 0 0 0 0 0\n3 0 -4 0.7 -0.1 0.1 0\n5 0 1 0 0 0 0\n"}}) {
        INFO(each.view);
        const auto dat = folder.write(std::string(each.view) + ".dat", each.points);
        const std::string sif = (folder / (std::string(each.view) + ".sif")).string();
        REQUIRE(run_apcs({"export", dat.string(), "--sif", sif, "--view", each.view}).status == 0);
        const auto original = run_apcs({"path", dat.string(), "--view", each.view, "--print"});
        const auto again = run_apcs({"path", sif, "--view", each.view, "--print"});
        REQUIRE(again.status == 0);
        CHECK(again.err.empty());
        CHECK(again.out == original.out);
    }
    const auto missing = run_apcs({"path", (folder / "top.sif").string(), "--sif-param", "offset"});
    CHECK(missing.status == 1);
    CHECK(missing.err.find("no layer has an animated vector `offset`") != std::string::npos);
}

TEST_CASE("The session's path prompt reads a Synfig document and writes the adjusted path to aniK.dat",
          "[cli][sif][session]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    // way1.dat seen from the front: (y, z) = (0, 0), (−4, 5), (0, 10), read back as (0, y, z).
    REQUIRE(run_apcs({"export", (folder / "way1.dat").string(), "--sif", (folder / "way1.sif").string(), "--view",
                      "front"})
                .status == 0);
    const auto script = folder.write("sif.keys", "ENTER\nENTER\nTEXT 0 90 200\nENTER\nTEXT way1.sif\nENTER\nENTER\n8\n"
                                                 "6\nENTER\nENTER\nENTER\nENTER\nTEXT n\nENTER\n");
    const auto result = run_apcs({"--keys", script.string(), "--workdir", folder.path().string(), "--glyphs", "ascii"});
    INFO(result.out << result.err);
    REQUIRE(std::filesystem::exists(folder / "ani1.dat"));
    const std::string adjusted = text_of(folder / "ani1.dat");
    // Tension 0.05 (one 6) on each control point of (0, 0, 0), (0, −4, 5), (0, 0, 10).
    CHECK(adjusted.find("0 -4 5 0.05 0 0 0") != std::string::npos);
    CHECK(text_of(folder / "way1.sif").starts_with("<?xml"));
}

TEST_CASE("Options that would be ignored are refused: --sif-param on a .dat, one path's options on an animation",
          "[cli][sif]")
{
    const TempFolder folder;
    test::write_small_example(folder);
    const auto param = run_apcs({"path", (folder / "way1.dat").string(), "--sif-param", "offset"});
    CHECK(param.status == 2);
    CHECK(param.err.find("--sif-param names what to read of a Synfig document (FILE.sif)") != std::string::npos);
    for (const char* option : {"--sif-motion", "--frames-per-span"}) {
        const auto animation =
            run_apcs({"export", (folder / "key1.dat").string(), (folder / "key2.dat").string(),
                      (folder / "way1.dat").string(), (folder / "way4.dat").string(), "--sif", "-", option,
                      std::string(option) == "--sif-motion" ? "frames" : "6"});
        CHECK(animation.status == 2);
        CHECK(animation.err.find(std::string(option) + " shapes one path's document") != std::string::npos);
    }
}
