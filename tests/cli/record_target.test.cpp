#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <fcntl.h>
#include <iostream>
#include <unistd.h>

using namespace apcs;
using test::read_all;
using test::run_apcs;
using test::TempFolder;

namespace {

// A copy of the N to L example, so that the session's writes do not touch data/.
void copy_n_to_l(const TempFolder& folder)
{
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "data" / "n-to-l"))
        std::filesystem::copy_file(entry.path(), folder / entry.path().filename().string());
}

test::CommandRun record_n_to_l(const TempFolder& folder, const std::string& target)
{
    return run_apcs({"--keys", (folder / "session.keys").string(), "--workdir", folder.path().string(), "--glyphs",
                     "ascii", "--record", target});
}

} // namespace

TEST_CASE("a recording (--record) refuses, before the session runs, every file the session uses", "[cli][session][record][files]")
{
    // Issue 33: each of these was replaced by the recorded keys (session.keys 1525 → 227 bytes).
    const char* name = GENERATE("session.keys", "way1.dat", "WAY4.DAT", "ani1.dat", "inb001.dat", "apcs.log");
    CAPTURE(name);
    const TempFolder folder;
    copy_n_to_l(folder);
    folder.write("apcs.log", "an earlier session\n");
    folder.write("ani1.dat", "0 0 0\n1 1 1\n");
    folder.write("inb001.dat", "0 0 0\n1 1 1\n");
    const std::string before = read_all(folder / name);
    const std::string way1 = read_all(folder / "way1.dat");

    const auto run = record_n_to_l(folder, (folder / name).string());

    CAPTURE(run.err);
    CHECK(run.status == 1);
    CHECK(run.err.find("--record never writes over it") != std::string::npos);
    CHECK(run.out.empty()); // the session never ran
    CHECK(read_all(folder / name) == before);
    CHECK(read_all(folder / "way1.dat") == way1);
}

TEST_CASE("a recording (--record) into a folder that does not exist is refused before the session runs", "[cli][session][record][files]")
{
    const TempFolder folder;
    copy_n_to_l(folder);
    const auto run = record_n_to_l(folder, (folder / "missing" / "again.keys").string());
    CHECK(run.status == 1);
    CHECK(run.err.find("again.keys: cannot be written: its folder") != std::string::npos);
    CHECK(run.out.empty());
    CHECK_FALSE(std::filesystem::exists(folder / "way1.bak")); // the session wrote nothing
}

TEST_CASE("a recording to - (--record -) goes to standard output, not to a file named -", "[cli][session][record]")
{
    const TempFolder folder;
    copy_n_to_l(folder);
    // The command refuses --record - when descriptor 1 is a terminal, as it may be where the tests
    // are run by hand: the run has it on /dev/null (the recording itself goes to the run's stream).
    std::cout.flush();
    const int saved_stdout = ::dup(STDOUT_FILENO);
    const int null = ::open("/dev/null", O_WRONLY);
    REQUIRE((saved_stdout >= 0 && null >= 0 && ::dup2(null, STDOUT_FILENO) == STDOUT_FILENO));
    const auto recorded = record_n_to_l(folder, "-");
    ::dup2(saved_stdout, STDOUT_FILENO);
    ::close(null);
    ::close(saved_stdout);
    CAPTURE(recorded.err);
    REQUIRE(recorded.status == 0);
    CHECK_FALSE(std::filesystem::exists("-"));
    // The script's inputs, keys and captions, no screens.
    CHECK(recorded.out.starts_with("INPUT key1.dat\nINPUT key2.dat\nINPUT way1.dat\nINPUT way4.dat\n;; Step 1 (fig. 4.2.1): KEY1 and KEY2, the two key frames: an N and an L\nENTER\nENTER\n;; "
                                   "Step 2 (fig. 4.2.2): points added, one path file each; now the view, face-on\nTEXT 0 90 "
                                   "100\nENTER\n"));
}

TEST_CASE("a recording (--record) never replaces a key file whose name was typed key by key, nor backs up over one",
          "[cli][session][record][files]")
{
    const TempFolder folder;
    copy_n_to_l(folder);
    const std::string key = read_all(folder / "key1.dat");

    // KEY1 typed one character at a time names the record target: no start-up check sees it.
    folder.write("n.dat", key);
    folder.write("typed.keys", "n . d a t ENTER\nENTER\n");
    const auto typed = run_apcs({"--keys", (folder / "typed.keys").string(), "--workdir", folder.path().string(),
                                 "--record", (folder / "n.dat").string()});
    CHECK(typed.status == 1);
    CHECK(typed.err.find("n.dat: is a key file; key files are never written (the keystrokes were not recorded)") !=
          std::string::npos);
    CHECK(read_all(folder / "n.dat") == key);

    // KEY1 is k.bak: the old recording k.keys is kept as k.b01, never as the key's k.bak.
    folder.write("k.bak", key);
    folder.write("k.keys", "old recording\n");
    folder.write("kb.keys", "TEXT k.bak\nENTER\nENTER\n");
    const auto backed = run_apcs({"--keys", (folder / "kb.keys").string(), "--workdir", folder.path().string(),
                                  "--record", (folder / "k.keys").string()});
    CHECK(backed.status == 0);
    CHECK(read_all(folder / "k.bak") == key);
    CHECK(read_all(folder / "k.b01") == "old recording\n");
}
