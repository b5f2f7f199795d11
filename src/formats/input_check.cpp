#include "apcs/formats/input_check.h"

#include "apcs/formats/file_io.h"
#include "posix_files.h"

#include <zlib.h>

namespace apcs {

using namespace posix_files;

namespace {

// Whose input it is: an exercise names its inputs' bytes, a lesson their presence (script_input.h).
std::string owner_of(const ScriptInput& input) { return input.crc32 ? "exercise" : "lesson"; }

// What to do about an input that is not the script's, in the folder `role` names.
std::string copy_again(const ScriptInput& input, InputFolder role)
{
    return role == InputFolder::work ? "copy the " + owner_of(input) + "'s files into the work folder again"
                                     : "put the exercise's files, as shipped, beside it again";
}

// The CRC-32 of the rest of an open file.
Expected<std::uint32_t> crc32_of_descriptor(int descriptor)
{
    uLong crc = ::crc32(0L, Z_NULL, 0);
    unsigned char buffer[1 << 16];
    while (true) {
        const ssize_t got = ::read(descriptor, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return Diagnostic{"", 0, "cannot be read: " + system_reason(errno)};
        if (got == 0)
            return static_cast<std::uint32_t>(crc);
        crc = ::crc32(crc, buffer, static_cast<uInt>(got));
    }
}

// A lesson's input: a regular file of its own, whatever its bytes (not read).
Expected<void> check_presence(const ScriptInput& input, const std::filesystem::path& file)
{
    struct stat status {};
    if (::lstat(file.c_str(), &status) != 0)
        return Diagnostic{"", 0, input.name + " cannot be read: " + system_reason(errno)};
    if (!S_ISREG(status.st_mode))
        return Diagnostic{"", 0, input.name + " is " + kind_of(status.st_mode) +
                                     "; expected the lesson's input, a regular file of its own: " +
                                     copy_again(input, InputFolder::work)};
    return ok;
}

// The input's problem, if any, as "NAME what; expected …": an exercise's file's bytes checked
// against its CRC-32, a lesson's file found.
Expected<void> check_input(const ScriptInput& input, const std::filesystem::path& folder, InputFolder role)
{
    const std::string where = role == InputFolder::work ? "the work folder " : "the exercise's folder ";
    // An input is looked for as the session will read it: a name in another case is the same file
    // (find_input_path, as DOS compared names).
    const Expected<std::filesystem::path> found = find_input_path(folder / input.name);
    if (!found)
        return Diagnostic{"", 0, input.name + " " + found.error().message};
    struct stat status {};
    if (::lstat(found->c_str(), &status) != 0 && errno == ENOENT)
        return Diagnostic{"", 0,
                          input.name + " is missing from " + where + folder.string() + "; expected the " +
                              owner_of(input) + "'s input: " + copy_again(input, role)};
    if (!input.crc32)
        return check_presence(input, *found);
    const Expected<std::uint32_t> crc32 = file_crc32(*found);
    if (!crc32)
        return Diagnostic{"", 0, input.name + " " + crc32.error().message + ": " + copy_again(input, role)};
    if (*crc32 != *input.crc32)
        return Diagnostic{"", 0,
                          input.name + " differs from the exercise's (CRC-32 " + crc32_text(*crc32) + ", expected " +
                              crc32_text(*input.crc32) + "): a session rewrote it, or it is another exercise's; " +
                              copy_again(input, role)};
    return ok;
}

} // namespace

Expected<std::uint32_t> file_crc32(const std::filesystem::path& file)
{
    struct stat status {};
    if (::lstat(file.c_str(), &status) != 0)
        return Diagnostic{"", 0, "cannot be read: " + system_reason(errno)};
    const std::string expected = "; expected the exercise's input, a regular file of its own";
    if (!S_ISREG(status.st_mode))
        return Diagnostic{"", 0, "is " + kind_of(status.st_mode) + expected};
    // O_NOFOLLOW and O_NONBLOCK, then fstat: a file swapped for a link or a FIFO since lstat is
    // refused, not followed or waited on.
    FileDescriptor descriptor(::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY));
    if (descriptor.get() < 0)
        return Diagnostic{"", 0, "cannot be read: " + system_reason(errno)};
    if (::fstat(descriptor.get(), &status) != 0 || !S_ISREG(status.st_mode))
        return Diagnostic{"", 0, "is " + kind_of(status.st_mode) + expected};
    return crc32_of_descriptor(descriptor.get());
}

Expected<void> check_script_inputs(const std::vector<ScriptInput>& inputs, const std::filesystem::path& folder,
                                   const std::string& script_name, InputFolder role)
{
    for (const ScriptInput& input : inputs)
        if (const Expected<void> checked = check_input(input, folder, role); !checked)
            return Diagnostic{script_name, input.line_number, checked.error().message};
    return ok;
}

} // namespace apcs
