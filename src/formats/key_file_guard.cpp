#include "apcs/formats/key_file_guard.h"

#include "apcs/formats/file_io.h"
#include "apcs/formats/text_fields.h"

#include <algorithm>

namespace apcs {

namespace fs = std::filesystem;

namespace {

// The name compared ignoring case: absolute when the current folder is known, so that "x.dat"
// and "/here/x.dat" compare equal even before either exists; lexically normal, so that "./x.dat"
// and "a/../x.dat" do too.
std::string comparable_name(const fs::path& file)
{
    std::error_code error;
    const fs::path absolute = fs::absolute(file, error);
    return (error ? file : absolute).lexically_normal().string();
}

} // namespace

void KeyFileGuard::protect(const fs::path& key_file)
{
    const fs::path resolved = resolve_input_path(key_file);
    m_key_files.push_back({resolved, comparable_name(resolved)});
}

bool KeyFileGuard::guards(const fs::path& target) const
{
    const std::string target_name = comparable_name(target);
    // A target not written yet is one file with no key: one stat instead of two per key (the
    // split asks this for every one of its 10^5 new files).
    std::error_code missing;
    const bool target_exists = fs::exists(fs::status(target, missing));
    return std::any_of(m_key_files.begin(), m_key_files.end(), [&](const KeyFile& key) {
        return (target_exists && fs::equivalent(target, key.path, missing)) ||
               equals_ignoring_case(target_name, key.comparable_name);
    });
}

Expected<void> KeyFileGuard::may_write(const fs::path& target) const
{
    if (guards(target))
        return Diagnostic{target.string(), 0, "is a key file; key files are never written"};
    return ok;
}

} // namespace apcs
