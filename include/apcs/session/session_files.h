#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/graphic.h"
#include "apcs/formats/dat_file.h"
#include "apcs/base/diagnostic.h"
#include "apcs/formats/key_file_guard.h"
#include "apcs/base/step_log.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace apcs {

// The session's only door to files, so that its steps stay free of I/O and can be driven in tests
// with any store. Names are as typed at the prompts; diagnostics name them the same way.
// A .dat file as read: its points, and its text, whose comments a rewrite keeps.
struct DatText {
    DatFile file;
    std::string text;
};

class SessionFiles : public StepLog {
public:
    // The whole text of a file (a regular file; FILE: reason otherwise).
    [[nodiscard]] virtual Expected<std::string> read_text(const std::string& name) = 0;
    // The file parsed as .dat (FILE:LINE: reason when it is not one).
    [[nodiscard]] Expected<DatFile> read_dat(const std::string& name, std::size_t minimum_points);
    [[nodiscard]] Expected<DatText> read_dat_text(const std::string& name, std::size_t minimum_points);
    // Whether anything has the name (a new picture takes a name that nothing has).
    [[nodiscard]] virtual bool exists(const std::string& name) const = 0;
    // The name of the file that read_dat(name) reads: another case of `name` where only that
    // exists (DOS names: WAY1.DAT reads way1.dat), so a rewrite goes back to the same file.
    [[nodiscard]] virtual std::string name_read(const std::string& name) const { return name; }
    // Whether `name` is one of the key files, under any spelling.
    [[nodiscard]] virtual bool is_key_file(const std::string& name) const = 0;
    // Whether `name` names a file of the session's folder or below it, and not, through '..', an
    // absolute name or a symbolic link, a file elsewhere (the path file is rewritten there).
    [[nodiscard]] virtual bool lies_in_folder(const std::string& name) const;
    // From now on `name` is a key file, which no write may replace (SPEC §2.1).
    virtual void protect_key_file(const std::string& name) = 0;
    // Atomic, keeping a differing old file as .bak; refuses a key file. The problem, if any.
    [[nodiscard]] virtual Expected<void> write(const std::string& name, const std::string& content) = 0;
    // Many writes in a row (the split's path files, one per point): from begin_batch() on, each
    // write stays atomic but does not wait for the disk; end_batch() then flushes them all at
    // once, one barrier instead of one per file. The problem of the barrier, if any.
    virtual void begin_batch() {}
    [[nodiscard]] virtual Expected<void> end_batch() { return ok; }
    // The in-betweens inb001.dat … (every frame but the first and the last), each a whole graphic
    // with the parts of `structure`; nothing is written if any of them is a key file. Returns the
    // names written.
    [[nodiscard]] virtual Expected<std::vector<std::string>> write_inbetweens(const FrameSequence& frames,
                                                                             const Graphic& structure) = 0;
    // The in-between files numbered above `written_count` that an earlier run left (never deleted).
    [[nodiscard]] virtual std::vector<std::string> earlier_inbetweens(std::size_t written_count) const = 0;
};

// Files in a folder: names are relative to it (an absolute name is used as it is); apcs.log is
// appended to there.
class FolderFiles final : public SessionFiles {
public:
    explicit FolderFiles(std::filesystem::path folder) : m_folder(std::move(folder)) {}
    // A batch still open (the program stopped mid-split) is flushed, so no file is left to chance.
    ~FolderFiles() override;
    FolderFiles(const FolderFiles&) = delete;
    FolderFiles& operator=(const FolderFiles&) = delete;

    Expected<std::string> read_text(const std::string& name) override;
    bool exists(const std::string& name) const override;
    std::string name_read(const std::string& name) const override;
    bool lies_in_folder(const std::string& name) const override;
    bool is_key_file(const std::string& name) const override { return m_key_files.guards(m_folder / name); }
    void protect_key_file(const std::string& name) override;
    Expected<void> write(const std::string& name, const std::string& content) override;
    void begin_batch() override { m_in_batch = true; }
    Expected<void> end_batch() override;
    Expected<std::vector<std::string>> write_inbetweens(const FrameSequence& frames, const Graphic& structure) override;
    std::vector<std::string> earlier_inbetweens(std::size_t written_count) const override;
    void log(const std::string& line) override;

private:
    // A diagnostic about a file of the folder, named as the user typed it.
    Diagnostic as_typed(Diagnostic problem) const;

    std::filesystem::path m_folder;
    KeyFileGuard m_key_files;
    bool m_in_batch = false;
};

// Files kept in memory: what a session reads, writes and logs, with no disk (tests, the fuzzer,
// and anyone driving the session from code).
class MemoryFiles final : public SessionFiles {
public:
    std::map<std::string, std::string> files;
    std::vector<std::string> log_lines;
    // Every write, in order, with repeats.
    std::vector<std::string> writes;
    // Batches begun and ended (end_batch is the disk barrier of a FolderFiles).
    int batches_begun = 0;
    int batches_ended = 0;

    Expected<std::string> read_text(const std::string& name) override;
    bool exists(const std::string& name) const override { return files.count(name) > 0; }
    bool is_key_file(const std::string& name) const override { return m_key_files.guards(name); }
    void protect_key_file(const std::string& name) override;
    Expected<void> write(const std::string& name, const std::string& content) override;
    void begin_batch() override { ++batches_begun; }
    Expected<void> end_batch() override
    {
        ++batches_ended;
        return ok;
    }
    Expected<std::vector<std::string>> write_inbetweens(const FrameSequence& frames, const Graphic& structure) override;
    std::vector<std::string> earlier_inbetweens(std::size_t written_count) const override;
    void log(const std::string& line) override { log_lines.push_back(line); }

private:
    KeyFileGuard m_key_files;
};

} // namespace apcs
