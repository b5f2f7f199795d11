#include "apcs/formats/file_io.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <future>
#include <thread>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <string>
#include <vector>

using namespace apcs;
using test::read_all;
using test::TempFolder;

TEST_CASE("a missing name finds the file that differs only in case", "[formats][files]")
{
    const TempFolder folder;
    folder.write("key1.dat", "0 0\n1 1\n");
    REQUIRE(resolve_input_path(folder / "KEY1.DAT") == folder / "key1.dat");
    const Expected<DatFile> file = read_dat_file(folder / "KEY1.DAT");
    REQUIRE(file.has_value());
    REQUIRE(file->point_count() == 2);
}

TEST_CASE("the exact name wins over case variants, and several variants without it are ambiguous",
          "[formats][files]")
{
    const TempFolder folder;
    folder.write("Case.dat", "0 0\n1 1\n");
    folder.write("case.DAT", "0 0\n1 1\n2 2\n");
    REQUIRE(read_dat_file(folder / "Case.dat")->point_count() == 2);
    REQUIRE(read_dat_file(folder / "case.DAT")->point_count() == 3);
    const std::string typed = (folder / "CASE.dat").string();
    const Expected<DatFile> ambiguous = read_dat_file(typed);
    REQUIRE_FALSE(ambiguous.has_value());
    REQUIRE(ambiguous.error().to_string() ==
            typed + ": is ambiguous: Case.dat and case.DAT differ only in case; expected the exact name");
}

TEST_CASE("reading a missing file or a folder names the file", "[formats][files]")
{
    const TempFolder folder;
    const std::string missing = (folder / "none.dat").string();
    REQUIRE(read_dat_file(missing).error().to_string() == missing + ": cannot open: No such file or directory");
    REQUIRE(read_dat_file(folder.path()).error().to_string() == folder.path().string() + ": is a directory; expected a file");
}

TEST_CASE("an atomic write creates, keeps identical files untouched and backs up changed ones", "[formats][files]")
{
    const TempFolder folder;
    const auto target = folder / "way1.dat";
    Expected<WriteResult> first = write_file_atomically(target, "0 0 0\n1 1 1\n");
    REQUIRE(first.has_value());
    REQUIRE(first->outcome == WriteOutcome::created);
    REQUIRE(read_all(target) == "0 0 0\n1 1 1\n");
    REQUIRE_FALSE(std::filesystem::exists(folder / "way1.bak"));

    REQUIRE(write_file_atomically(target, "0 0 0\n1 1 1\n")->outcome == WriteOutcome::unchanged);
    REQUIRE_FALSE(std::filesystem::exists(folder / "way1.bak"));

    const Expected<WriteResult> changed = write_file_atomically(target, "0 0 0\n2 2 2\n");
    REQUIRE(changed->outcome == WriteOutcome::replaced);
    REQUIRE(changed->backup == folder / "way1.bak");
    REQUIRE(read_all(target) == "0 0 0\n2 2 2\n");
    REQUIRE(read_all(folder / "way1.bak") == "0 0 0\n1 1 1\n");

    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder.path()))
        ++entries;
    REQUIRE(entries == 2); // no temporary file left behind
}

namespace {

// A content writer giving `chunks` one by one, as the streamed in-between files do.
ContentWriter chunks_of(std::vector<std::string> chunks)
{
    return [chunks = std::move(chunks)](const ContentSink& sink) {
        for (const std::string& chunk : chunks)
            if (!sink(chunk))
                return;
    };
}

} // namespace

TEST_CASE("content written chunk by chunk: the same is only compared, a difference anywhere replaces the file",
          "[formats][files]")
{
    const TempFolder folder;
    const auto target = folder / "inb001.dat";
    // 200 000 bytes in chunks of 70 000: the comparison and the copy of the equal part cross the
    // 64 KiB pieces they read in.
    const std::string old_content(200000, 'a');
    REQUIRE(write_file_atomically(target, chunks_of({old_content.substr(0, 70000), old_content.substr(70000)}))->outcome ==
            WriteOutcome::created);
    REQUIRE(read_all(target) == old_content);

    struct stat before {};
    REQUIRE(::stat(target.c_str(), &before) == 0);
    REQUIRE(write_file_atomically(target, chunks_of({old_content.substr(0, 70000), old_content.substr(70000, 70000),
                                                     old_content.substr(140000)}))
                ->outcome == WriteOutcome::unchanged);
    struct stat after {};
    REQUIRE(::stat(target.c_str(), &after) == 0);
    REQUIRE(after.st_ino == before.st_ino); // not even replaced by an equal copy

    std::string changed = old_content;
    changed[150000] = 'b'; // in the third chunk
    const Expected<WriteResult> replaced = write_file_atomically(
        target, chunks_of({changed.substr(0, 70000), changed.substr(70000, 70000), changed.substr(140000)}));
    REQUIRE(replaced->outcome == WriteOutcome::replaced);
    REQUIRE(read_all(target) == changed);
    REQUIRE(read_all(folder / "inb001.bak") == old_content);

    // The old content's beginning only, and the old content and more: both differ.
    REQUIRE(write_file_atomically(target, chunks_of({changed.substr(0, 100000)}))->outcome == WriteOutcome::replaced);
    REQUIRE(read_all(target) == changed.substr(0, 100000));
    REQUIRE(write_file_atomically(target, chunks_of({changed.substr(0, 100000), "tail"}))->outcome ==
            WriteOutcome::replaced);
    REQUIRE(read_all(target) == changed.substr(0, 100000) + "tail");
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder.path()))
        ++entries;
    REQUIRE(entries == 2); // the file and its .bak: no temporary file left behind
}

TEST_CASE("unchanged content chunk by chunk makes no temporary file: the folder is not touched", "[formats][files]")
{
    const TempFolder folder;
    const auto target = folder.write("inb001.dat", "1 2 3\n");
    struct stat before {};
    REQUIRE(::stat(folder.path().c_str(), &before) == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(20)); // a made and removed file would show in the mtime
    CHECK(write_file_atomically(target, chunks_of({"1 2", " 3\n"}))->outcome == WriteOutcome::unchanged);
    struct stat after {};
    REQUIRE(::stat(folder.path().c_str(), &after) == 0);
    CHECK(after.st_mtim.tv_sec == before.st_mtim.tv_sec);
    CHECK(after.st_mtim.tv_nsec == before.st_mtim.tv_nsec);
    // A difference makes one, and the folder changes.
    CHECK(write_file_atomically(target, chunks_of({"1 2", " 4\n"}))->outcome == WriteOutcome::replaced);
    REQUIRE(::stat(folder.path().c_str(), &after) == 0);
    CHECK((after.st_mtim.tv_sec != before.st_mtim.tv_sec || after.st_mtim.tv_nsec != before.st_mtim.tv_nsec));
}

TEST_CASE("names up to the file system's longest (255 bytes) are written, created and replaced", "[formats][files]")
{
    const TempFolder folder;
    std::string utf8_name = "x";
    for (int i = 0; i < 125; ++i)
        utf8_name += "\xC3\xA9"; // é
    utf8_name += ".dat";
    REQUIRE(utf8_name.size() == 255);
    for (const std::string& name : {std::string(245, 'a') + ".dat", std::string(251, 'b') + ".dat", utf8_name}) {
        const auto target = folder / name;
        INFO(name.size() << "-byte name");
        const Expected<WriteResult> created = write_file_atomically(target, "0 0\n1 1\n");
        if (!created)
            FAIL(created.error().to_string());
        const Expected<WriteResult> replaced = write_file_atomically(target, "0 0\n2 2\n");
        REQUIRE(replaced.has_value());
        REQUIRE(replaced->outcome == WriteOutcome::replaced);
        REQUIRE(read_all(target) == "0 0\n2 2\n");
    }
    std::size_t entries = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
        entries += entry.path().filename().string().starts_with('.') ? std::size_t{100} : std::size_t{1};
    REQUIRE(entries == 6); // three files and their .bak, no temporary file left behind
}

TEST_CASE("a failed write reports why and leaves no file", "[formats][files]")
{
    const TempFolder folder;
    const Expected<WriteResult> into_missing = write_file_atomically(folder / "no/such/way1.dat", "1 1\n");
    REQUIRE_FALSE(into_missing.has_value());
    REQUIRE(into_missing.error().message.starts_with("cannot create a temporary file in"));

    std::filesystem::create_directory(folder / "taken.dat");
    const Expected<WriteResult> over_folder = write_file_atomically(folder / "taken.dat", "1 1\n");
    REQUIRE(over_folder.error().message == "is a directory; cannot write a file there");
    REQUIRE(std::filesystem::is_directory(folder / "taken.dat"));
}

TEST_CASE("the backup of a .bak file is not the file itself", "[formats][files]")
{
    REQUIRE(backup_path_for("a/way1.dat") == "a/way1.bak");
    REQUIRE(backup_path_for("way1.bak") == "way1.bak.bak");
    REQUIRE(backup_path_for("noext") == "noext.bak");
}

namespace {

namespace fs = std::filesystem;

// Makes a FIFO named `name` in `folder`; false when the file system cannot hold one.
bool make_fifo(const fs::path& fifo) { return ::mkfifo(fifo.c_str(), 0644) == 0; }

// Reads `name` on another thread; a read still blocked after 5 s is released (a writer opens and
// closes the FIFO, which ends the read) and reported as a hang instead of hanging the suite.
Expected<std::string> read_without_hanging(const fs::path& name, bool& hung)
{
    auto reading = std::async(std::launch::async, [name] { return read_text_file(name); });
    hung = reading.wait_for(std::chrono::seconds(5)) != std::future_status::ready;
    if (hung) {
        const int writer = ::open(name.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
        if (writer >= 0)
            ::close(writer);
    }
    return reading.get();
}

bool is_regular_file_not_link(const fs::path& file)
{
    std::error_code error;
    return fs::symlink_status(file, error).type() == fs::file_type::regular;
}

mode_t mode_of(const fs::path& file)
{
    struct stat status {};
    REQUIRE(::stat(file.c_str(), &status) == 0);
    return status.st_mode & 07777;
}

std::size_t entries_in(const fs::path& folder)
{
    std::size_t entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder))
        ++entries;
    return entries;
}

} // namespace

TEST_CASE("a FIFO given as an input file is refused at once, never waited on", "[formats][files][special]")
{
    const TempFolder folder;
    const fs::path fifo = folder / "key1.dat";
    const bool made = make_fifo(fifo);
    INFO("cannot make a FIFO in " << folder.path() << ": " << std::strerror(errno));
    REQUIRE(made);
    bool hung = false;
    const Expected<std::string> text = read_without_hanging(fifo, hung);
    REQUIRE_FALSE(hung);
    REQUIRE_FALSE(text.has_value());
    REQUIRE(text.error().to_string() == fifo.string() + ": is not a regular file (a FIFO); expected a file");

    // The same through a symbolic link, through a name that differs in case, and as a .dat file.
    fs::create_symlink(fifo, folder / "link.dat");
    REQUIRE(read_without_hanging(folder / "link.dat", hung).error().message == "is not a regular file (a FIFO); expected a file");
    REQUIRE_FALSE(hung);
    REQUIRE(read_without_hanging(folder / "KEY1.DAT", hung).error().message == "is not a regular file (a FIFO); expected a file");
    REQUIRE_FALSE(hung);
    REQUIRE(read_dat_file(fifo).error().message == "is not a regular file (a FIFO); expected a file");
}

TEST_CASE("a device given as an input file is refused without reading it", "[formats][files][special]")
{
    REQUIRE(fs::is_character_file("/dev/zero"));
    REQUIRE(fs::is_character_file("/dev/null"));
    REQUIRE(read_text_file("/dev/zero").error().to_string() == "/dev/zero: is not a regular file (a character device); expected a file");
    REQUIRE(read_text_file("/dev/null").error().message == "is not a regular file (a character device); expected a file");
    const TempFolder folder;
    fs::create_symlink("/dev/null", folder / "null.dat");
    REQUIRE(read_dat_file(folder / "null.dat").error().message == "is not a regular file (a character device); expected a file");
}

TEST_CASE("a write never replaces a FIFO, and never opens it", "[formats][files][special]")
{
    const TempFolder folder;
    const fs::path fifo = folder / "out.png";
    const bool made = make_fifo(fifo);
    INFO("cannot make a FIFO in " << folder.path() << ": " << std::strerror(errno));
    REQUIRE(made);
    const Expected<WriteResult> written = write_file_atomically(fifo, "PNG");
    REQUIRE_FALSE(written.has_value());
    REQUIRE(written.error().to_string() == fifo.string() + ": is not a regular file (a FIFO); APCS writes only regular files");
    REQUIRE(fs::is_fifo(fs::symlink_status(fifo)));
    REQUIRE(entries_in(folder.path()) == 1); // no .bak, no temporary file
}

TEST_CASE("a write through a symbolic link replaces the regular file it names and keeps the link", "[formats][files][special]")
{
    const TempFolder folder;
    fs::create_directory(folder / "real");
    const fs::path real = folder.write("real/way1.dat", "0 0 0\n1 1 1\n");
    const fs::path link = folder / "way1.dat";
    fs::create_symlink("real/way1.dat", link);

    const Expected<WriteResult> written = write_file_atomically(link, "0 0 0\n2 2 2\n");
    REQUIRE(written.has_value());
    REQUIRE(written->outcome == WriteOutcome::replaced);
    REQUIRE(fs::is_symlink(link));
    REQUIRE(fs::read_symlink(link) == "real/way1.dat");
    REQUIRE(is_regular_file_not_link(real));
    REQUIRE(read_all(real) == "0 0 0\n2 2 2\n");
    // The old content is kept beside the file the link names, in its own folder.
    REQUIRE(fs::equivalent(written->backup, folder / "real/way1.bak"));
    REQUIRE(read_all(folder / "real/way1.bak") == "0 0 0\n1 1 1\n");
    REQUIRE_FALSE(fs::exists(fs::symlink_status(folder / "way1.bak")));
    REQUIRE(entries_in(folder.path()) == 2);
    REQUIRE(entries_in(folder / "real") == 2);
}

TEST_CASE("a write through a symbolic link, or a chain of them, that leads out of its folder is refused",
          "[formats][files][special][links]")
{
    const TempFolder folder;
    fs::create_directories(folder / "victim");
    fs::create_directories(folder / "w");
    const fs::path victim = folder.write("victim/passwd", "root:x:0:0\n");
    const fs::path link = folder / "w/my.keys";
    fs::create_symlink("../victim/passwd", link);
    fs::create_symlink("hop.keys", folder / "w/chain.keys");
    fs::create_symlink("../victim/passwd", folder / "w/hop.keys");

    for (const fs::path& output : {link, folder / "w/chain.keys"}) {
        const Expected<WriteResult> written = write_file_atomically(output, "KEY Enter\n");
        REQUIRE_FALSE(written.has_value());
        REQUIRE(written.error().file == output.string());
        REQUIRE(written.error().message.ends_with(", which leads out of its folder (to " +
                                                  fs::canonical(victim).string() +
                                                  "); APCS writes through a link only to a file in the link's folder or below it"));
        REQUIRE_FALSE(check_writable(output).has_value());
    }
    REQUIRE(write_file_atomically(link, "x").error().message.starts_with("is a symbolic link to ../victim/passwd, which"));
    REQUIRE(read_all(victim) == "root:x:0:0\n");
    REQUIRE(entries_in(folder / "victim") == 1); // no passwd.bak, no temporary file
    REQUIRE(entries_in(folder / "w") == 3);
}

TEST_CASE("a symbolic link to a file in its own folder or below it is written through", "[formats][files][special][links]")
{
    const TempFolder folder;
    fs::create_directories(folder / "w/pages");
    folder.write("w/pages/real.txt", "old\n");
    fs::create_symlink("pages/real.txt", folder / "w/below.txt");
    folder.write("w/beside.txt", "old\n");
    fs::create_symlink("beside.txt", folder / "w/same.txt");
    REQUIRE(check_link_stays_in_folder(folder / "w/below.txt").has_value());
    REQUIRE(check_link_stays_in_folder(folder / "w/same.txt").has_value());
    REQUIRE(check_link_stays_in_folder(folder / "w/beside.txt").has_value()); // not a link
    REQUIRE(write_file_atomically(folder / "w/below.txt", "new\n").has_value());
    REQUIRE(read_all(folder / "w/pages/real.txt") == "new\n");
}

TEST_CASE("a file written through an opened folder goes into that folder after it is renamed and replaced by a link",
          "[formats][files][special][links]")
{
    const TempFolder folder;
    fs::create_directories(folder / "out");
    fs::create_directories(folder / "other");
    const Expected<OutputFolder> opened = OutputFolder::open(folder / "out");
    REQUIRE(opened.has_value());
    REQUIRE(write_file_atomically(*opened, "frm000.dat", std::string_view("0 0\n")).has_value());
    fs::rename(folder / "out", folder / "out.moved");
    fs::create_directory_symlink("other", folder / "out");

    const Expected<WriteResult> written = write_file_atomically(*opened, "frm001.dat", std::string_view("1 1\n"));
    REQUIRE(written.has_value());
    REQUIRE(read_all(folder / "out.moved/frm001.dat") == "1 1\n");
    REQUIRE(entries_in(folder / "other") == 0);
    REQUIRE(entries_in(folder / "out.moved") == 2);
    // Replaced there too, its old content kept beside it; messages name it as the folder was named.
    const Expected<WriteResult> again = write_file_atomically(*opened, "frm001.dat", std::string_view("2 2\n"));
    REQUIRE(again.has_value());
    REQUIRE(read_all(folder / "out.moved/frm001.bak") == "1 1\n");
    fs::create_directory(folder / "out.moved/frm002.dat");
    const Expected<WriteResult> refused = write_file_atomically(*opened, "frm002.dat", std::string_view("3 3\n"));
    REQUIRE_FALSE(refused.has_value());
    REQUIRE(refused.error().to_string() == (folder / "out/frm002.dat").string() + ": is a directory; cannot write a file there");
}

TEST_CASE("a write through a symbolic link to a device or to nothing is refused", "[formats][files][special]")
{
    const TempFolder folder;
    // Only inspected: /dev/null is never written by this test, and the refusal comes first.
    if (fs::exists("/dev/null")) {
        const fs::path to_null = folder / "null.png";
        fs::create_symlink("/dev/null", to_null);
        const Expected<WriteResult> written = write_file_atomically(to_null, "PNG");
        REQUIRE_FALSE(written.has_value());
        REQUIRE(written.error().message ==
                "is a symbolic link to /dev/null, which is not a regular file (a character device); APCS writes only regular files");
        REQUIRE(fs::is_symlink(to_null));
        REQUIRE(fs::is_character_file("/dev/null"));
    }
    const fs::path dangling = folder / "gone.dat";
    fs::create_symlink(folder / "missing/none.dat", dangling);
    const Expected<WriteResult> into_nothing = write_file_atomically(dangling, "1 1\n");
    REQUIRE_FALSE(into_nothing.has_value());
    REQUIRE(into_nothing.error().message.starts_with("is a symbolic link to " + (folder / "missing/none.dat").string() + ", which does not exist"));
    REQUIRE(fs::is_symlink(dangling));
}

// Making a device node needs root (CAP_MKNOD), so this test is hidden from the default run and
// from the per-test list: CTest runs it as "device nodes (mknod): a write never replaces a device
// node" through tests/support/mknod_or_skip.sh, which reports a skip (77) where the user is not
// root and cannot make one. As root it always runs, and a node it cannot make is a failure.
TEST_CASE("a write never replaces a device node", "[.][formats][files][special][mknod]")
{
    const TempFolder folder;
    const fs::path device = folder / "X";
    // /dev/null's numbers, 1 3.
    const bool made = ::mknod(device.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;
    INFO("mknod " << device << ": " << std::strerror(errno));
    REQUIRE(made);
    const Expected<WriteResult> written = write_file_atomically(device, "PNG");
    REQUIRE_FALSE(written.has_value());
    REQUIRE(written.error().message == "is not a regular file (a character device); APCS writes only regular files");
    REQUIRE(fs::is_character_file(fs::symlink_status(device)));
    REQUIRE(entries_in(folder.path()) == 1);
}

TEST_CASE("rewriting a file keeps its mode", "[formats][files][mode]")
{
    const TempFolder folder;
    const fs::path secret = folder.write("secret.dat", "0 0\n1 1\n");
    fs::permissions(secret, fs::perms::owner_read | fs::perms::owner_write);
    REQUIRE(mode_of(secret) == 0600);
    REQUIRE(write_file_atomically(secret, "0 0\n2 2\n")->outcome == WriteOutcome::replaced);
    REQUIRE(read_all(secret) == "0 0\n2 2\n");
    REQUIRE(mode_of(secret) == 0600);

    const fs::path shared = folder.write("shared.dat", "0 0\n1 1\n");
    ::chmod(shared.c_str(), 0664);
    REQUIRE(write_file_atomically(shared, "0 0\n2 2\n").has_value());
    REQUIRE(mode_of(shared) == 0664);

    // A new file is 0644 as before.
    REQUIRE(write_file_atomically(folder / "new.dat", "0 0\n1 1\n").has_value());
    REQUIRE(mode_of(folder / "new.dat") == 0644);
}

TEST_CASE("a read-only file is refused, not replaced", "[formats][files][mode]")
{
    const TempFolder folder;
    const fs::path locked = folder.write("locked.dat", "0 0\n1 1\n");
    ::chmod(locked.c_str(), 0444);
    // Also as root, who may write anything: the mode bits say the user does not want it written.
    const Expected<WriteResult> written = write_file_atomically(locked, "0 0\n2 2\n");
    REQUIRE_FALSE(written.has_value());
    REQUIRE(written.error().to_string() == locked.string() + ": is read-only (mode 0444); not replaced");
    REQUIRE(read_all(locked) == "0 0\n1 1\n");
    REQUIRE(mode_of(locked) == 0444);
    REQUIRE(entries_in(folder.path()) == 1);
    // Identical content writes nothing, so there is nothing to refuse.
    REQUIRE(write_file_atomically(locked, "0 0\n1 1\n")->outcome == WriteOutcome::unchanged);
}

TEST_CASE("a backup never replaces an input: the old file goes to NAME.b01 when NAME.bak is a key file",
          "[formats][files]")
{
    const TempFolder folder;
    const auto key = folder.write("ani1.bak", "0 0 0\n1 1 1\n");
    const auto target = folder.write("ani1.dat", "old\n");
    folder.write("ani1.b01", "someone's\n");
    KeyFileGuard inputs;
    inputs.protect(key);
    const Expected<WriteResult> written = write_file_atomically(target, "new\n", &inputs);
    REQUIRE(written.has_value());
    REQUIRE(read_all(key) == "0 0 0\n1 1 1\n");
    REQUIRE(read_all(target) == "new\n");
    // ani1.b01 exists already: the old file takes the next free number.
    REQUIRE(written->backup == folder / "ani1.b02");
    REQUIRE(read_all(folder / "ani1.b02") == "old\n");
    REQUIRE(read_all(folder / "ani1.b01") == "someone's\n");
    // Without inputs, .bak is replaced as always.
    REQUIRE(write_file_atomically(target, "newer\n")->backup == folder / "ani1.bak");
}

TEST_CASE("writes left for one barrier are atomic and keep backups as ever — the barrier names a missing folder",
          "[formats][files]")
{
    const TempFolder folder;
    const auto target = folder.write("ani1.dat", "old\n");
    const Expected<WriteResult> replaced = write_file_atomically(target, "new\n", nullptr, Durability::at_barrier);
    REQUIRE(replaced.has_value());
    REQUIRE(replaced->outcome == WriteOutcome::replaced);
    REQUIRE(read_all(target) == "new\n");
    REQUIRE(read_all(folder / "ani1.bak") == "old\n");
    REQUIRE(write_file_atomically(folder / "ani2.dat", "2\n", nullptr, Durability::at_barrier)->outcome ==
            WriteOutcome::created);
    for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
        REQUIRE(entry.path().filename().string().front() != '.');
    REQUIRE(flush_file_system(folder.path()).has_value());
    const Expected<void> missing = flush_file_system(folder / "no-such-folder");
    REQUIRE_FALSE(missing.has_value());
    REQUIRE(missing.error().to_string() == (folder / "no-such-folder").string() +
                                        ": cannot flush the files written to disk: No such file or directory");
}

TEST_CASE("a .bak that is a FIFO, a link, a directory or read-only is never replaced by the old file",
          "[formats][files]")
{
    const TempFolder folder;
    folder.write("way1.dat", "1 1 1\n2 2 2\n");
    const auto refused_with = [&](const std::string& reason) {
        const Expected<WriteResult> written = write_file_atomically(folder / "way1.dat", "3 3 3\n4 4 4\n");
        REQUIRE_FALSE(written);
        CHECK(written.error().message ==
              "cannot keep the old file as " + (folder / "way1.bak").string() + ": it " + reason);
        CHECK(read_all(folder / "way1.dat") == "1 1 1\n2 2 2\n");
    };
    REQUIRE(::mkfifo((folder / "way1.bak").c_str(), 0644) == 0);
    refused_with("is not a regular file (a FIFO); a backup replaces only a regular file");
    CHECK(std::filesystem::is_fifo(folder / "way1.bak"));
    std::filesystem::remove(folder / "way1.bak");

    std::filesystem::create_symlink("/dev/null", folder / "way1.bak");
    refused_with("is a symbolic link; a backup replaces only a regular file");
    CHECK(std::filesystem::is_symlink(folder / "way1.bak"));
    std::filesystem::remove(folder / "way1.bak");

    std::filesystem::create_directory(folder / "way1.bak");
    refused_with("is a directory; a backup replaces only a regular file");
    std::filesystem::remove(folder / "way1.bak");

    // Read-only for root too: no write bit at all.
    folder.write("way1.bak", "older\n");
    std::filesystem::permissions(folder / "way1.bak", std::filesystem::perms::owner_read);
    refused_with("is read-only (mode 0400); not replaced");
    CHECK(read_all(folder / "way1.bak") == "older\n");
}
