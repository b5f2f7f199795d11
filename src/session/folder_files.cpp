#include "apcs/session/session_files.h"

#include "apcs/formats/file_io.h"

#include <fstream>

namespace apcs {

Expected<DatFile> FolderFiles::read_dat(const std::string& name, std::size_t minimum_points)
{
    const Expected<std::string> text = read_text_file(m_folder / name);
    if (!text)
        return Diagnostic{name, 0, text.error().message};
    return parse_dat(*text, name, minimum_points);
}

std::optional<Diagnostic> FolderFiles::write(const std::string& name, const std::string& content)
{
    const Expected<WriteResult> result = write_file_atomically(m_folder / name, content);
    if (!result)
        return Diagnostic{name, 0, result.error().message};
    return std::nullopt;
}

void FolderFiles::log(const std::string& line)
{
    // The log is the session's own record, appended line by line so that it survives a stop.
    std::ofstream(m_folder / "apcs.log", std::ios::app) << line << '\n';
}

} // namespace apcs
