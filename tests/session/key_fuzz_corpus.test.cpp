#include "fuzz/session_keystrokes.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;

TEST_CASE("every key stream of the session fuzzing corpus plays without a crash and writes only in the folder",
          "[session][fuzz]")
{
    std::size_t streams = 0;
    std::size_t reached_fitting = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "tests/fuzz/session")) {
        const std::string bytes = test::read_all(entry.path());
        const MemoryFiles files = fuzzing::play_keystrokes(
            {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
        ++streams;
        REQUIRE(fuzzing::writes_stay_in_folder(files));
        reached_fitting += files.files.count("inb001.dat");
    }
    REQUIRE(streams > 100);
    // The corpus reaches the end of the session, not only its first prompts.
    REQUIRE(reached_fitting > 0);
}
