#pragma once

#include "apcs/session/session_files.h"

#include <map>
#include <set>
#include <string>

namespace apcs {

// The session's files for a replay that can go back (PgUp, Home: SPEC §3.1). It passes everything
// to the folder's files and keeps each file as it was when the session first read it, before the
// session wrote it. rewind() starts over: the next session reads the files as they were at the
// start and writes only to memory, logging nothing, until caught_up(); from then on it writes to
// the folder again, as the replay that first went that way did.
class RewindableFiles final : public SessionFiles {
public:
    explicit RewindableFiles(SessionFiles& folder) : m_folder(folder) {}

    void rewind();
    void caught_up() { m_catching_up = false; }

    Expected<std::string> read_text(const std::string& name) override;
    bool exists(const std::string& name) const override;
    std::string name_read(const std::string& name) const override { return m_folder.name_read(name); }
    bool lies_in_folder(const std::string& name) const override { return m_folder.lies_in_folder(name); }
    bool is_key_file(const std::string& name) const override
    {
        return m_folder.is_key_file(name) || m_memory.is_key_file(name);
    }
    void protect_key_file(const std::string& name) override;
    Expected<void> write(const std::string& name, const std::string& content) override;
    void begin_batch() override;
    Expected<void> end_batch() override;
    Expected<std::vector<std::string>> write_inbetweens(const FrameSequence& frames, const Graphic& structure) override;
    std::vector<std::string> earlier_inbetweens(std::size_t written_count) const override;
    void log(const std::string& line) override;

private:
    // A file as it was before the session wrote it: whether it existed, and its text once read.
    struct AsStarted {
        bool exists = false;
        std::optional<Expected<std::string>> text;
    };
    void written_to_folder(const std::string& name);

    SessionFiles& m_folder;
    MemoryFiles m_memory; // what a session written since the last rewind() wrote while catching up
    bool m_catching_up = false;
    std::set<std::string> m_written_since_rewind; // to the folder: read from there
    std::set<std::string> m_ever_written;         // to the folder: no longer as it started
    mutable std::map<std::string, AsStarted> m_as_started;
};

} // namespace apcs
