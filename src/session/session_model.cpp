#include "apcs/session/session_model.h"

#include <cassert>

namespace apcs {

void WrittenFiles::add(const std::string& name)
{
    if (m_known.insert(name).second)
        m_names.push_back(name);
}

Expected<void> StepContext::write_file(const std::string& name, const std::string& content)
{
    Expected<void> written = files.write(name, content);
    if (!written)
        model.written.set_problem(written.error());
    return written;
}

PathSettings StepContext::path_settings(int path) const
{
    assert(path == 0 || path == 1);
    return {model.paths[static_cast<std::size_t>(path)].slopes, settings.samples_per_segment, settings.inbetween_count,
            settings.spacing};
}

} // namespace apcs
