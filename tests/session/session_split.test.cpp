// The split of large keys: written a batch per Session::work(), with a progress line, stopped by
// Esc with every file written so far whole, and one disk barrier for all its files.
#include "apcs/formats/file_io.h"
#include "apcs/formats/path_files.h"
#include "apcs/session/session.h"
#include "apcs/session/session_files.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

using namespace apcs;

namespace {

// A key of `count` points on one open part, different for KEY1 and KEY2.
std::string large_key(int count, int which)
{
    std::string text = "PART cloud OPEN\n";
    for (int i = 0; i < count; ++i)
        text += std::to_string(i) + " " + std::to_string(i % 7 + which) + " " + std::to_string(which) + "\n";
    return text;
}

void submit_default(Session& session) { session.handle(KeyEvent::of(Key::enter)); }

std::string last_row(const Session& session)
{
    std::string row = session.screen().text.row_text(TextConsole::rows - 1);
    return row.erase(row.find_last_not_of(' ') + 1);
}

std::string screen_text(const Session& session)
{
    const CellGrid grid = session.screen().text;
    std::string shown;
    for (int row = 0; row < grid.rows(); ++row)
        shown += grid.row_text(row) + "\n";
    return shown;
}

constexpr int large_count = 1000;

MemoryFiles large_keys()
{
    MemoryFiles files;
    files.files["key1.dat"] = large_key(large_count, 1);
    files.files["key2.dat"] = large_key(large_count, 2);
    return files;
}

// How many of ani1.dat … aniN.dat the store holds, counted from ani1.dat until one is missing.
int path_files_in(const MemoryFiles& files)
{
    int count = 0;
    while (files.files.count(path_file_name(static_cast<std::size_t>(count + 1))) > 0)
        ++count;
    return count;
}

} // namespace

TEST_CASE("a large split goes on in work() and shows its progress on the message line", "[session][split]")
{
    MemoryFiles files = large_keys();
    Session session({}, files);
    submit_default(session);
    submit_default(session);
    REQUIRE(session.busy());
    REQUIRE(session.leaf_name() == "splitting");
    const int first_batch = path_files_in(files);
    REQUIRE(first_batch > 0);
    REQUIRE(first_batch < large_count);
    REQUIRE(last_row(session) == "Splitting: " + path_file_name(static_cast<std::size_t>(first_batch)) + " of 1000 written - "
                                 "Esc stops, Ctrl-C ends APCS");
    session.work();
    REQUIRE(path_files_in(files) > first_batch);
    while (session.busy())
        session.work();
    REQUIRE(session.leaf_name() == "ask_view");
    REQUIRE(path_files_in(files) == large_count);
    REQUIRE(files.writes.size() == static_cast<std::size_t>(large_count));
    // The split's files are the thesis' (split_path_file), and its one barrier came after them.
    REQUIRE(files.files["ani1000.dat"] == "999 6 1\n999 7 2\n");
    REQUIRE(files.batches_begun == 1);
    REQUIRE(files.batches_ended == 1);
    REQUIRE(files.log_lines.back() == "added points: both keys have 1000 points in 1 parts; wrote ani1.dat … ani1000.dat");
    REQUIRE(last_row(session).find("Splitting") == std::string::npos);
}

TEST_CASE("Esc stops the split: the files written stay, KEY2 is asked again", "[session][split]")
{
    MemoryFiles files = large_keys();
    Session session({}, files);
    submit_default(session);
    submit_default(session);
    session.work();
    const int written = path_files_in(files);
    session.handle(KeyEvent::of(Key::escape));
    REQUIRE_FALSE(session.busy());
    REQUIRE(session.leaf_name() == "ask_key2");
    session.work(); // nothing more to do
    REQUIRE(path_files_in(files) == written);
    REQUIRE(files.writes.size() == static_cast<std::size_t>(written));
    REQUIRE(files.batches_ended == 1);
    const std::string stopped = "Split stopped: ani1.dat … " + path_file_name(static_cast<std::size_t>(written)) + " (" +
                                std::to_string(written) + " of 1000) written, none half-written";
    REQUIRE(screen_text(session).find(stopped) != std::string::npos);
    REQUIRE(screen_text(session).find("Please keyin the KEY2 filename!") != std::string::npos);
    // Asked again, KEY2 starts the split over and finishes it.
    submit_default(session);
    while (session.busy())
        session.work();
    REQUIRE(session.leaf_name() == "ask_view");
    REQUIRE(path_files_in(files) == large_count);
}

TEST_CASE("keys other than Esc and Q mean nothing while splitting — Q ends APCS with the files whole",
          "[session][split]")
{
    MemoryFiles files = large_keys();
    Session session({}, files);
    submit_default(session);
    submit_default(session);
    session.handle(KeyEvent::typed(U'x'));
    session.handle(KeyEvent::of(Key::enter));
    REQUIRE(session.busy());
    session.handle(KeyEvent::typed(U'q'));
    REQUIRE(session.finished());
    REQUIRE_FALSE(session.busy());
    REQUIRE(files.batches_ended == 1);
    REQUIRE(path_files_in(files) < large_count);
}

TEST_CASE("keys of a batch or fewer points are split at once, as the thesis did", "[session][split]")
{
    MemoryFiles files;
    files.files["key1.dat"] = large_key(10, 1);
    files.files["key2.dat"] = large_key(10, 2);
    Session session({}, files);
    submit_default(session);
    submit_default(session);
    REQUIRE_FALSE(session.busy());
    REQUIRE(session.leaf_name() == "ask_view");
    REQUIRE(path_files_in(files) == 10);
    REQUIRE(files.batches_ended == 1);
}

TEST_CASE("a split stopped in a folder leaves whole files and no temporary file", "[session][split]")
{
    const test::TempFolder folder;
    folder.write("key1.dat", large_key(large_count, 1));
    folder.write("key2.dat", large_key(large_count, 2));
    {
        FolderFiles files(folder.path());
        Session session({}, files);
        submit_default(session);
        submit_default(session);
        session.work();
        session.handle(KeyEvent::of(Key::escape));
        REQUIRE(session.leaf_name() == "ask_key2");
    }
    int path_files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder.path())) {
        const std::string name = entry.path().filename().string();
        REQUIRE(name.front() != '.');
        if (name.starts_with("ani")) {
            ++path_files;
            REQUIRE(read_dat_file(entry.path()).has_value());
        }
    }
    REQUIRE(path_files > 0);
    REQUIRE(path_files < large_count);
    REQUIRE(std::filesystem::exists(folder / path_file_name(static_cast<std::size_t>(path_files))));
}

TEST_CASE("a headless session writes every path file of a large split", "[session][split][headless]")
{
    const test::TempFolder folder;
    folder.write("key1.dat", large_key(large_count, 1));
    folder.write("key2.dat", large_key(large_count, 2));
    folder.write("split.keys", "ENTER\nENTER\n");
    const auto result = test::run_apcs({"--keys", (folder / "split.keys").string(), "--workdir", folder.path().string()});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.find("--- step 2: view and delay") != std::string::npos);
    REQUIRE(result.out.find("Splitting") == std::string::npos);
    for (const int number : {1, 500, large_count})
        REQUIRE(std::filesystem::exists(folder / path_file_name(static_cast<std::size_t>(number))));
    REQUIRE_FALSE(std::filesystem::exists(folder / path_file_name(large_count + 1)));
}
