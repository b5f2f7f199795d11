#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/path_files.h"
#include "apcs/session/session_files.h"

namespace apcs {

Expected<std::string> MemoryFiles::read_text(const std::string& name)
{
    const auto found = files.find(name);
    if (found == files.end())
        return Diagnostic{name, 0, "cannot open: No such file or directory"};
    return found->second;
}

void MemoryFiles::protect_key_file(const std::string& name) { m_key_files.protect(name); }

Expected<void> MemoryFiles::write(const std::string& name, const std::string& content)
{
    if (m_key_files.guards(name))
        return Diagnostic{name, 0, "is a key file; key files are never written"};
    files[name] = content;
    writes.push_back(name);
    return ok;
}

Expected<std::vector<std::string>> MemoryFiles::write_inbetweens(const FrameSequence& frames, const Graphic& structure)
{
    const std::size_t count = inbetween_count(frames);
    for (std::size_t number = 1; number <= count; ++number)
        if (m_key_files.guards(inbetween_file_name(number)))
            return Diagnostic{inbetween_file_name(number), 0, "is a key file; key files are never written"};
    std::vector<std::string> names;
    for (std::size_t number = 1; number <= count; ++number) {
        NamedText file = inbetween_file(frames, structure, number);
        files[file.name] = std::move(file.content);
        writes.push_back(file.name);
        names.push_back(file.name);
    }
    return names;
}

std::vector<std::string> MemoryFiles::earlier_inbetweens(std::size_t written_count) const
{
    std::vector<std::string> names;
    for (const auto& [name, content] : files)
        names.push_back(name);
    return inbetweens_beyond(names, written_count);
}

} // namespace apcs
