#include "apcs/formats/file_io.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

using namespace apcs;
using test::TempFolder;

namespace {

// Bytes this process has read through read() so far, as Linux counts them (/proc/self/io).
std::uint64_t bytes_read_so_far()
{
    std::ifstream io("/proc/self/io");
    std::string key;
    std::uint64_t value = 0;
    while (io >> key >> value)
        if (key == "rchar:")
            return value;
    return 0;
}

} // namespace

TEST_CASE("a 64 MiB file with a NUL byte first is refused after reading its first chunk", "[formats][memory]")
{
    const TempFolder folder;
    std::string text(1, '\0');
    const std::string line = "1 2 3\n";
    while (text.size() < (64u << 20))
        text += line;
    const std::filesystem::path file = folder.write("binary.dat", text);
    text.clear();
    text.shrink_to_fit();
    const std::uint64_t before = bytes_read_so_far();
    const Expected<std::string> read = read_text_file(file);
    const std::uint64_t read_bytes = bytes_read_so_far() - before;
    REQUIRE_FALSE(read);
    CHECK(read.error().to_string() == file.string() + ":1: NUL byte; expected a text file");
    CHECK(read_bytes < (1u << 20));
}

TEST_CASE("a NUL byte is reported on its line", "[formats][memory]")
{
    const TempFolder folder;
    const std::filesystem::path file = folder.write("late.dat", std::string("0 0 0\n1 1 1\n2 2\0 2\n", 18));
    const Expected<std::string> read = read_text_file(file);
    REQUIRE_FALSE(read);
    CHECK(read.error().to_string() == file.string() + ":3: NUL byte; expected a text file");
}

TEST_CASE("a file over 1 GiB is refused by its size without being read", "[formats][memory]")
{
    const TempFolder folder;
    const std::filesystem::path file = folder.write("huge.dat", "0 0 0\n");
    // Sparse: no disk space is taken.
    std::filesystem::resize_file(file, (1ull << 30) + 1);
    const std::uint64_t before = bytes_read_so_far();
    const Expected<std::string> read = read_text_file(file);
    const std::uint64_t read_bytes = bytes_read_so_far() - before;
    REQUIRE_FALSE(read);
    CHECK(read.error().to_string() == file.string() + ": is 1073741825 bytes; expected at most 1073741824 bytes (1 GiB)");
    CHECK(read_bytes < (1u << 20));
}
