// libFuzzer harness: any bytes as a .scn file (fuzz/scene_input.h). The reader must return a scene
// or a diagnostic, never crash or hang; a scene read must evaluate every frame, each point finite.
#include "scene_input.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    if (apcs::fuzzing::read_and_play_scene(text) == apcs::fuzzing::SceneOutcome::broken)
        std::abort();
    return 0;
}
