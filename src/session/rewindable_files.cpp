#include "apcs/session/rewindable_files.h"

namespace apcs {

void RewindableFiles::rewind()
{
    m_memory = MemoryFiles();
    m_written_since_rewind.clear();
    m_catching_up = true;
}

Expected<std::string> RewindableFiles::read_text(const std::string& name)
{
    if (m_memory.exists(name))
        return m_memory.read_text(name);
    if (m_written_since_rewind.contains(name))
        return m_folder.read_text(name);
    AsStarted& started = m_as_started[name];
    if (started.text)
        return *started.text;
    Expected<std::string> text = m_folder.read_text(name);
    // A file the session wrote is no longer as it started: what it was is not known.
    if (!m_ever_written.contains(name)) {
        started.exists = text.has_value() || m_folder.exists(name);
        started.text = text;
    }
    return text;
}

bool RewindableFiles::exists(const std::string& name) const
{
    if (m_memory.exists(name))
        return true;
    if (m_written_since_rewind.contains(name))
        return m_folder.exists(name);
    if (const auto started = m_as_started.find(name); started != m_as_started.end())
        return started->second.exists;
    // Written before anything asked for it: catching up, the replay writes it again before it asks.
    if (m_ever_written.contains(name))
        return !m_catching_up && m_folder.exists(name);
    const bool there = m_folder.exists(name);
    m_as_started[name].exists = there;
    return there;
}

void RewindableFiles::protect_key_file(const std::string& name)
{
    m_folder.protect_key_file(name);
    m_memory.protect_key_file(name);
}

void RewindableFiles::written_to_folder(const std::string& name)
{
    m_written_since_rewind.insert(name);
    m_ever_written.insert(name);
    m_memory.files.erase(name);
}

Expected<void> RewindableFiles::write(const std::string& name, const std::string& content)
{
    if (m_catching_up)
        return m_memory.write(name, content);
    Expected<void> written = m_folder.write(name, content);
    if (written)
        written_to_folder(name);
    return written;
}

void RewindableFiles::begin_batch()
{
    if (!m_catching_up)
        m_folder.begin_batch();
}

Expected<void> RewindableFiles::end_batch() { return m_catching_up ? ok : m_folder.end_batch(); }

Expected<std::vector<std::string>> RewindableFiles::write_inbetweens(const FrameSequence& frames,
                                                                    const Graphic& structure)
{
    if (m_catching_up)
        return m_memory.write_inbetweens(frames, structure);
    Expected<std::vector<std::string>> names = m_folder.write_inbetweens(frames, structure);
    if (names)
        for (const std::string& name : *names)
            written_to_folder(name);
    return names;
}

std::vector<std::string> RewindableFiles::earlier_inbetweens(std::size_t written_count) const
{
    return m_catching_up ? m_memory.earlier_inbetweens(written_count) : m_folder.earlier_inbetweens(written_count);
}

void RewindableFiles::log(const std::string& line)
{
    if (!m_catching_up)
        m_folder.log(line);
}

} // namespace apcs
