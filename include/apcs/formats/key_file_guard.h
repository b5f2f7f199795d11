#pragma once

#include "apcs/base/diagnostic.h"

#include <filesystem>
#include <string>
#include <vector>

namespace apcs {

// The key files of a run, which APCS reads and never writes. A target is a key file when both
// exist and the file system says they are one file (hard links, symbolic links, "./x", another
// case on a case-insensitive file system), or else when their absolute, lexically normal names
// are equal ignoring ASCII case, as DOS compared names (the thesis' files are DOS names, and a
// file not written yet can only be compared by name).
class KeyFileGuard {
public:
    // Guards `key_file` from now on. A name that does not exist stands for the file of its folder
    // that differs only in case, as when the key was read (resolve_input_path).
    void protect(const std::filesystem::path& key_file);

    [[nodiscard]] bool guards(const std::filesystem::path& target) const;

    // ok when `target` is not guarded; else "TARGET: is a key file; key files are never written".
    Expected<void> may_write(const std::filesystem::path& target) const;

private:
    struct KeyFile {
        std::filesystem::path path;
        // The absolute, lexically normal name, for comparing ignoring case.
        std::string comparable_name;
    };

    std::vector<KeyFile> m_key_files;
};

} // namespace apcs
