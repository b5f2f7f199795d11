#pragma once

// The session over a real folder (FolderFiles) full of hostile entries: FIFOs, links to devices,
// dangling links, directories named like .dat files, a link out of the folder, a read-only file,
// case variants, very long names and hard links to the key files. Shared by the libFuzzer harness
// and the Catch test that replays its corpus, so both play the same sessions and check the same
// invariants.
//
// An input's first two bytes each put one hostile entry where the session writes (an ani, inb or
// png file, a .bak); every later byte is one key, as in session_keystrokes.h, except that bytes
// 0xC0 and up type one of the folder's names and Enter.

#include "folder_snapshot.h"
#include "session_keystrokes.h"

#include "apcs/formats/file_io.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <optional>
#include <set>
#include <sstream>
#include <unistd.h>

namespace apcs::fuzzing {

namespace hostile {

namespace fs = std::filesystem;

inline const std::string key1_text = "0 0 0\n0 0 10\n0 6 0\n0 6 10\n";
inline const std::string key2_text = "0 0 10\n0 0 0\n0 5 0\n";
inline const std::string other_key_text = "1 1 1\n1 1 11\n1 7 1\n1 7 11\n";
inline const std::string path_text = "0 0 0\n3 -4 5\n0 0 10\n";
inline constexpr int inbetweens = 3; // few, so that a run reaches its in-between files quickly

// Names a user could type; 200 bytes is the longest answer a prompt takes.
inline const std::string long_name = std::string(196, 'l') + ".dat";
inline const std::string longest_name = std::string(251, 'm') + ".dat"; // 255 bytes: NAME_MAX

inline void write_text(const fs::path& file, const std::string& text)
{
    std::ofstream(file, std::ios::binary) << text;
}

inline void put_read_only(const fs::path& file, const std::string& text)
{
    write_text(file, text);
    fs::permissions(file, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
}

// The entries that are there in every run.
inline void populate(const fs::path& work, const fs::path& outside)
{
    write_text(outside / "way1.dat", path_text);
    write_text(outside / "victim.dat", key1_text);
    write_text(work / "key1.dat", key1_text);
    write_text(work / "key2.dat", key2_text);
    write_text(work / "Key1.DAT", other_key_text);
    write_text(work / "way1.dat", path_text);
    write_text(work / "way2.dat", path_text);
    write_text(work / long_name, path_text);
    write_text(work / longest_name, path_text);
    fs::create_hard_link(work / "key1.dat", work / "keyhard.dat");
    fs::create_hard_link(work / "key2.dat", work / "key2hard.dat");
    fs::create_symlink("key1.dat", work / "keylink.dat");
    ::mkfifo((work / "fifo.dat").c_str(), 0644);
    fs::create_symlink("/dev/null", work / "null.dat");
    fs::create_symlink("missing.dat", work / "dangling.dat");
    fs::create_directory(work / "dir.dat");
    write_text(work / "dir.dat" / "inner.dat", path_text);
    fs::create_symlink("../outside", work / "out");
    put_read_only(work / "readonly.dat", path_text);
}

// The four highest choices leave an earlier run's in-between files where the session writes its
// set, so that a set mixed of two runs would show: inb002.dat of an earlier run (252), its backup
// place taken by a folder (253), inb001.dat of an earlier run (254), and both at once (255).
inline bool place_earlier_run(const fs::path& work, std::uint8_t choice)
{
    if (choice < 252)
        return false;
    std::error_code error;
    if (choice != 253 && !fs::exists(fs::symlink_status(work / "inb002.dat", error)))
        write_text(work / "inb002.dat", path_text);
    if (choice == 253)
        fs::create_directory(work / "inb002.bak", error);
    if (choice >= 254 && !fs::exists(fs::symlink_status(work / "inb001.dat", error)))
        write_text(work / "inb001.dat", path_text);
    return true;
}

// One hostile entry at a name the session writes, chosen by one byte of the input.
inline void place_hostile_entry(const fs::path& work, std::uint8_t choice)
{
    if (place_earlier_run(work, choice))
        return;
    static const std::array<const char*, 9> targets = {"ani1.dat",   "ani2.dat",   "ani4.dat",
                                                       "inb001.dat", "inb002.dat", "inb003.dat",
                                                       "apcs001.png", "way1.bak",  "ani1.bak"};
    const fs::path entry = work / targets[choice % targets.size()];
    std::error_code error;
    if (fs::exists(fs::symlink_status(entry, error)))
        return;
    switch (choice / targets.size() % 7) {
    case 0: ::mkfifo(entry.c_str(), 0644); break;
    case 1: fs::create_symlink("/dev/null", entry, error); break;
    case 2: fs::create_symlink("nowhere.dat", entry, error); break;
    case 3: fs::create_directory(entry, error); break;
    case 4: put_read_only(entry, path_text); break;
    case 5: fs::create_hard_link(work / "key1.dat", entry, error); break;
    default: fs::create_symlink("key2.dat", entry, error); break;
    }
}

inline std::vector<std::string> answer_names(const fs::path& work)
{
    return {"key1.dat",     "key2.dat",     "Key1.DAT",          "KEY1.DAT",
            "KEY2.DAT",     "keyhard.dat",  "key2hard.dat",      "keylink.dat",
            "./key1.dat",   (work / "key1.dat").string(),        "way1.dat",
            "WAY1.DAT",     "way2.dat",     "fifo.dat",          "null.dat",
            "dangling.dat", "dir.dat",      "dir.dat/inner.dat", "out/way1.dat",
            "../outside/way1.dat",          "readonly.dat",      long_name,
            "ani1.dat",     "ani2.dat",     "inb001.dat",        "way1.bak",
            "ani1.bak",     "apcs.log"};
}

inline std::optional<FileIdentity> identity_of(const fs::path& file)
{
    struct stat status {};
    if (::stat(resolve_input_path(file).c_str(), &status) != 0)
        return std::nullopt;
    return FileIdentity{status.st_dev, status.st_ino};
}

// The key files in force before the session wrote anything: the first KEY1 and KEY2 its log names
// ("KEY1 name: 4 points in 1 parts"). A KEY2 asked again after a failed split is guarded only from
// then on, and files written before may have been that file: the invariants leave it out.
inline std::vector<std::string> first_keys(const fs::path& work)
{
    std::vector<std::string> names;
    std::istringstream log(bytes_of(work / "apcs.log"));
    for (std::string line; std::getline(log, line);) {
        const std::string prefix = names.empty() ? "KEY1 " : "KEY2 ";
        if (names.size() < 2 && line.starts_with(prefix) && line.rfind(": ") > prefix.size())
            names.push_back(line.substr(prefix.size(), line.rfind(": ") - prefix.size()));
    }
    return names;
}

inline std::string describe(const std::string& name, const EntryState& before, const EntryState& after)
{
    std::ostringstream text;
    text << name << ": mode " << std::oct << before.mode << " -> " << after.mode << std::dec << ", inode "
         << before.own.inode << " -> " << after.own.inode << ", link '" << before.link_target << "' -> '"
         << after.link_target << "', " << before.bytes.size() << " -> " << after.bytes.size() << " bytes";
    return text.str();
}

// Whether a session changed an entry as none may: a name of a key file or a read-only file in any
// way; any other entry that is not a regular file in what it is (type, inode, link text) - a link
// to a regular file is written through, so what it reaches may change.
inline bool changed_wrongly(const EntryState& before, const EntryState& after, const std::vector<FileIdentity>& keys)
{
    const bool key = before.reaches_file && std::find(keys.begin(), keys.end(), before.reached) != keys.end();
    if (key || (S_ISREG(before.mode) && (before.mode & 0222) == 0))
        return after != before;
    return !S_ISREG(before.mode) &&
           (after.mode != before.mode || after.own != before.own || after.link_target != before.link_target);
}

inline std::optional<std::string> check_invariants(const fs::path& root, const FolderState& work_before,
                                                   const FolderState& outside_before,
                                                   const std::vector<FileIdentity>& keys)
{
    const FolderState outside_after = snapshot(root / "outside");
    if (outside_after != outside_before)
        return "the folder outside the work folder changed";
    const FolderState work_after = snapshot(root / "work");
    for (const auto& [name, before] : work_before) {
        const auto after = work_after.find(name);
        if (after == work_after.end())
            return name + ": removed"; // a session removes only its own temporary files
        if (changed_wrongly(before, after->second, keys))
            return "replaced or changed: " + describe(name, before, after->second);
    }
    for (const auto& [name, after] : work_after)
        if (is_temporary_name(fs::path(name).filename().string()))
            return name + ": a temporary file was left behind";
    return std::nullopt;
}

// The in-between files a run wrote are a whole set or none (manual section 11): a set that stopped
// half way would leave a folder of frames from two runs.
inline std::optional<std::string> check_whole_set(const std::vector<std::string>& written, int set_size)
{
    std::set<std::string> inbetween_names;
    for (const std::string& name : written)
        if (name.starts_with("inb") && name.ends_with(".dat"))
            inbetween_names.insert(name);
    if (!inbetween_names.empty() && inbetween_names.size() != static_cast<std::size_t>(set_size))
        return "a partial set of in-between files: " + std::to_string(inbetween_names.size()) + " of " +
               std::to_string(set_size) + " written";
    return std::nullopt;
}

// A fresh folder for one run under `base`, removed with everything in it at the end.
class RunFolder {
public:
    explicit RunFolder(const fs::path& base)
    {
        static std::atomic<unsigned> runs{0};
        m_root = base / ("apcs-folder-fuzz-" + std::to_string(::getpid()) + "-" + std::to_string(runs++));
        fs::remove_all(m_root);
        fs::create_directories(m_root / "work");
        fs::create_directories(m_root / "outside");
    }
    RunFolder(const RunFolder&) = delete;
    RunFolder& operator=(const RunFolder&) = delete;
    ~RunFolder()
    {
        std::error_code ignored;
        fs::remove_all(m_root, ignored);
    }
    const fs::path& root() const { return m_root; }

private:
    fs::path m_root;
};

} // namespace hostile

struct FolderRun {
    // What went wrong, if an invariant broke.
    std::optional<std::string> violation;
    std::vector<std::string> written;
};

// Plays `bytes` over a fresh hostile folder and checks that no special file, read-only file, key
// file or file outside the folder changed and that no temporary file was left behind. A session
// that opens a FIFO for reading never returns: the fuzzer's timeout reports it. Every file written
// is flushed to disk, so a `base` in memory (/dev/shm) makes a run many times faster.
inline FolderRun play_in_hostile_folder(std::span<const std::uint8_t> bytes,
                                        const std::filesystem::path& base = std::filesystem::temp_directory_path())
{
    namespace fs = std::filesystem;
    const hostile::RunFolder folder(base);
    const fs::path work = folder.root() / "work";
    hostile::populate(work, folder.root() / "outside");
    for (std::size_t i = 0; i < 2 && i < bytes.size(); ++i)
        hostile::place_hostile_entry(work, bytes[i]);
    const std::vector<std::string> names = hostile::answer_names(work);
    std::map<std::string, std::optional<FileIdentity>> named_before;
    for (const std::string& name : names)
        named_before[name] = hostile::identity_of(work / name);
    const FolderState work_before = snapshot(work);
    const FolderState outside_before = snapshot(folder.root() / "outside");

    FolderRun run;
    {
        FolderFiles files(work);
        SessionSettings settings;
        settings.samples_per_segment = 4;
        settings.inbetween_count = hostile::inbetweens;
        Session session(settings, files);
        for (std::size_t i = 2; i < bytes.size() && !session.finished(); ++i) {
            if (bytes[i] >= 0xC0) {
                for (const char c : names[(bytes[i] - 0xC0u) % names.size()])
                    session.handle(KeyEvent::typed(static_cast<unsigned char>(c)));
                session.handle(KeyEvent::of(Key::enter));
            } else {
                session.handle(key_from(bytes[i]));
            }
            while (session.busy())
                session.work();
            for (int ticks = 0; session.animating() && ticks < 100; ++ticks)
                session.tick();
        }
        (void)session.screen();
        run.written = session.written_files();
    }
    std::vector<FileIdentity> keys;
    for (const std::string& name : hostile::first_keys(work)) {
        const auto found = named_before.find(name);
        if (found != named_before.end() && found->second)
            keys.push_back(*found->second);
    }
    run.violation = hostile::check_invariants(folder.root(), work_before, outside_before, keys);
    if (!run.violation)
        run.violation = hostile::check_whole_set(run.written, hostile::inbetweens);
    return run;
}

} // namespace apcs::fuzzing
