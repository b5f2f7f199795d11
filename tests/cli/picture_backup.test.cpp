#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace apcs;
using test::read_all;
using test::run_apcs;
using test::TempFolder;

namespace {

constexpr const char* old_picture = "the picture of an earlier run";

// One command that reads NAME.bak and writes a picture NAME.ext (issue 33): `inputs` are written
// before the run, the picture's old content is `old_picture`, and `arguments` name files by the
// folder's path ("@" stands for it).
struct PictureCase {
    const char* what;
    std::vector<std::pair<const char*, const char*>> inputs;
    std::vector<std::string> arguments;
    const char* picture;
    const char* backup_read;
};

std::vector<std::string> in_folder(const std::vector<std::string>& arguments, const TempFolder& folder)
{
    std::vector<std::string> placed;
    for (const std::string& argument : arguments)
        placed.push_back(argument.starts_with("@") ? (folder / argument.substr(1)).string() : argument);
    return placed;
}

} // namespace

TEST_CASE("a picture's backup never replaces a file the run reads: the old picture is kept as NAME.b01",
          "[cli][picture][files]")
{
    const char* key1 = "0 0 0\n0 0 10\n0 6 0\n0 6 10\n";
    const char* key2 = "0 0 10\n0 0 0\n0 5 0\n";
    const char* way = "0 0 0\n3 -4 5\n0 0 10\n";
    const PictureCase picture_case = GENERATE_COPY(values<PictureCase>({
        {"draw reading way1.bak", {{"way1.bak", way}, {"way1.dat", way}},
         {"draw", "@way1.bak", "@way1.dat", "--png", "@way1.png"}, "way1.png", "way1.bak"},
        {"path reading w.bak", {{"w.bak", way}}, {"path", "@w.bak", "--png", "@w.png"}, "w.png", "w.bak"},
        {"path --svg reading w.bak", {{"w.bak", way}}, {"path", "@w.bak", "--svg", "@w.svg"}, "w.svg", "w.bak"},
        {"fit reading kk.bak", {{"kk.bak", key1}, {"key2.dat", key2}, {"way1.dat", way}, {"way4.dat", "0 6 10\n-3 10 5\n0 5 0\n"}},
         {"fit", "@kk.bak", "@key2.dat", "@way1.dat", "@way4.dat", "--inbetweens", "2", "--gif", "@kk.gif"}, "kk.gif", "kk.bak"},
        {"inbetween reading ib.bak", {{"ib.bak", key1}, {"key2.dat", key2}},
         {"inbetween", "@ib.bak", "@key2.dat", "--frames", "2", "--svg", "@ib.svg"}, "ib.svg", "ib.bak"},
        {"play of a scene whose SHAPE is shp.bak", {{"shp.bak", way}, {"b.scn", "FRAMES 2\nOBJECT a\nSHAPE shp.bak\n"}},
         {"play", "@b.scn", "--png", "@shp.png"}, "shp.png", "shp.bak"},
    }));
    CAPTURE(picture_case.what);
    const TempFolder folder;
    for (const auto& [name, content] : picture_case.inputs)
        folder.write(name, content);
    folder.write(picture_case.picture, old_picture);
    const std::string read_before = read_all(folder / picture_case.backup_read);

    const auto run = run_apcs(in_folder(picture_case.arguments, folder));

    CAPTURE(run.err);
    REQUIRE(run.status == 0);
    CHECK(read_all(folder / picture_case.backup_read) == read_before);
    std::filesystem::path kept = folder / picture_case.picture;
    kept.replace_extension(".b01");
    CHECK(read_all(kept) == old_picture);
    CHECK(read_all(folder / picture_case.picture) != old_picture);
}
