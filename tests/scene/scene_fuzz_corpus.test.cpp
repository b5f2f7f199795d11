#include "fuzz/scene_input.h"

#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace apcs;

TEST_CASE("every scene of the .scn fuzzing corpus is refused with a message or plays with finite points",
          "[scene][fuzz]")
{
    std::size_t inputs = 0;
    std::size_t played = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(APCS_SOURCE_DIR) / "tests/fuzz/scene_reader")) {
        CAPTURE(entry.path().filename().string());
        const fuzzing::SceneOutcome outcome = fuzzing::read_and_play_scene(test::read_all(entry.path()));
        REQUIRE(outcome != fuzzing::SceneOutcome::broken);
        ++inputs;
        played += outcome == fuzzing::SceneOutcome::played ? 1u : 0u;
    }
    REQUIRE(inputs > 100);
    // The corpus reaches the frames, not only the reader's refusals.
    REQUIRE(played > 10);
}
