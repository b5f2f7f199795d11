#include "fuzz/hostile_folder.h"

#include "support/run_apcs.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sys/stat.h>
#include <string>
#include <vector>

using namespace apcs;
namespace fs = std::filesystem;

namespace {

// A batch run with an output the user names: `arguments` with "{T}" standing for the target, the
// files it reads (under the work folder) in `inputs`.
struct OutputCase {
    std::string what;
    std::vector<std::string> arguments;
    std::vector<std::string> inputs;
    std::string extension; // a picture's: its target names end so, as the option asks
};

const std::string way4_text = "0 6 10\n-3 10 5\n0 5 0\n";
const std::string script_text = "ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n8\nENTER\nENTER\nENTER\nENTER\nN\n";

std::vector<OutputCase> output_cases()
{
    return {
        {"path --png", {"path", "{W}/way1.dat", "--png", "{T}"}, {"way1.dat"}, ".png"},
        {"path --sixel", {"path", "{W}/way1.dat", "--sixel", "{T}"}, {"way1.dat"}, ".six"},
        {"draw --kitty", {"draw", "{W}/key1.dat", "{W}/key2.dat", "--kitty", "{T}"}, {"key1.dat", "key2.dat"},
         ".kitty"},
        // An input named as a picture's backup would be (way1.bak beside way1.png, PIC.bak).
        {"draw --svg", {"draw", "{W}/key1.dat", "{W}/way1.bak", "{W}/pic.bak", "--svg", "{T}"},
         {"key1.dat", "way1.bak", "pic.bak"}, ".svg"},
        {"fit --gif",
         {"fit", "{W}/key1.dat", "{W}/key2.dat", "{W}/way1.dat", "{W}/way4.dat", "--inbetweens", "2", "--gif", "{T}"},
         {"key1.dat", "key2.dat", "way1.dat", "way4.dat"}, ".gif"},
        {"inbetween --png-raw", {"inbetween", "{W}/key1.dat", "{W}/key2.dat", "--png-raw", "{T}"},
         {"key1.dat", "key2.dat"}, ".png"},
        {"session --record",
         {"--keys", "{W}/script.keys", "--workdir", "{W}", "--samples", "4", "--inbetweens", "2", "--record", "{T}"},
         // The session rewrites the path it shapes (way1.dat, keeping way1.bak): its inputs that
         // stay are the key files and the script.
         {"key1.dat", "key2.dat", "script.keys"}, ""},
    };
}

// Hostile entries with a picture's extension: a FIFO, links to a key file, to /dev/null and to
// nothing, a hard link to a key file, a folder, a read-only file, and a name whose backup is an
// input (way1 and pic: way1.bak and pic.bak are read).
std::vector<std::string> place_picture_entries(const fs::path& work, const std::string& extension)
{
    namespace hostile = fuzzing::hostile;
    const auto name = [&extension](const std::string& stem) { return stem + extension; };
    ::mkfifo((work / name("fifo")).c_str(), 0644);
    fs::create_symlink("key1.dat", work / name("keylink"));
    fs::create_symlink("/dev/null", work / name("null"));
    fs::create_symlink("missing" + extension, work / name("dangling"));
    fs::create_hard_link(work / "key1.dat", work / name("keyhard"));
    fs::create_directory(work / name("dir"));
    hostile::put_read_only(work / name("readonly"), "old picture\n");
    hostile::write_text(work / name("pic"), "an earlier picture\n");
    return {name("fifo"), name("keylink"), name("null"), name("dangling"), name("keyhard"), name("dir"),
            name("readonly"), name("pic"), name("way1"), name("WAY1"), name("new")};
}

std::vector<std::string> filled(std::vector<std::string> arguments, const fs::path& work, const fs::path& target)
{
    for (std::string& argument : arguments) {
        if (argument == "{T}")
            argument = target.string();
        else if (argument.starts_with("{W}"))
            argument = work.string() + argument.substr(3);
    }
    return arguments;
}

} // namespace

// Issue 33: pictures named after inputs, backups and links, and --record targets, as the folder
// fuzzer's hostile folder offers them. Whatever the name, no input, key file, read-only file or
// special entry changes, nothing outside the folder changes, no temporary file is left, and the
// run ends with a status (0, 1 or 2), never a hang or a crash.
TEST_CASE("outputs named after inputs, links, backups and special files leave every input and special file as it was",
          "[cli][fuzz]")
{
    std::size_t runs = 0;
    std::size_t refused = 0;
    for (const OutputCase& output : output_cases()) {
        std::vector<std::string> targets = fuzzing::hostile::answer_names("");
        targets.insert(targets.end(), {"way1.bak", "pic.bak", "script.keys", "way4.dat", "WAY4.DAT"});
        if (!output.extension.empty())
            targets = {"fifo", "keylink", "null", "dangling", "keyhard", "dir", "readonly", "pic", "way1", "WAY1", "new"};
        for (std::string name : targets) {
            if (name.starts_with("../") || name.starts_with("out/") || name.starts_with("/"))
                continue; // a name outside the work folder is the user's to write
            const fuzzing::hostile::RunFolder folder(fs::temp_directory_path());
            const fs::path work = folder.root() / "work";
            fuzzing::hostile::populate(work, folder.root() / "outside");
            fuzzing::hostile::write_text(work / "way4.dat", way4_text);
            fuzzing::hostile::write_text(work / "script.keys", script_text);
            fuzzing::hostile::write_text(work / "way1.bak", fuzzing::hostile::path_text);
            fuzzing::hostile::write_text(work / "pic.bak", fuzzing::hostile::path_text);
            if (!output.extension.empty()) {
                place_picture_entries(work, output.extension);
                name += output.extension;
            }
            std::vector<fuzzing::FileIdentity> inputs;
            for (const std::string& input : output.inputs)
                inputs.push_back(*fuzzing::hostile::identity_of(work / input));
            const fuzzing::FolderState work_before = fuzzing::snapshot(work);
            const fuzzing::FolderState outside_before = fuzzing::snapshot(folder.root() / "outside");
            CAPTURE(output.what, name);
            // Twice: the second run meets the first one's file (and makes its backup).
            for (int time = 0; time < 2; ++time) {
                const test::CommandRun run = test::run_apcs(filled(output.arguments, work, work / name));
                CAPTURE(run.err);
                REQUIRE((run.status == 0 || run.status == 1 || run.status == 2));
                refused += run.status != 0 ? 1u : 0u;
                ++runs;
            }
            const std::optional<std::string> violation =
                fuzzing::hostile::check_invariants(folder.root(), work_before, outside_before, inputs);
            REQUIRE(violation.value_or("") == "");
        }
    }
    REQUIRE(runs >= 150);
    // The hostile names are refused (key files, links to them, FIFOs, folders), not all written.
    REQUIRE(refused > 40);
}
