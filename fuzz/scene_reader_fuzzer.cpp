// libFuzzer harness: any bytes as a .scn file whose .dat files are a few small ones held in
// memory (any other name is missing). The reader must return a scene or a diagnostic, never crash
// or hang; a scene read must evaluate every frame, each point finite.
#include "apcs/formats/dat_file.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>

namespace {

const std::map<std::string, std::string> dat_files{
    {"a.dat", "PART sq CLOSED\n0 0 0\n0 1 0\n0 1 1\n0 0 1\n"},
    {"b.dat", "0 0 0\n0 1 0\n"},
    {"c.dat", "0 0 2\n0 1 2\n0 2 2\n"},
    {"p.dat", "0 0 0\n0 5 1\n0 10 0\n"},
    {"q.dat", "0 0 0 0.5 0 0 1\n0 3 0 0 0 0 -1\n"},
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const apcs::SceneFileReader read = [](const std::string& name) -> apcs::Expected<apcs::DatFile> {
        const auto found = dat_files.find(name);
        if (found == dat_files.end())
            return apcs::Diagnostic{name, 0, "no such file"};
        return apcs::parse_dat(found->second, name, 1);
    };
    const apcs::Expected<apcs::Scene> scene = apcs::parse_scene(text, "fuzz.scn", read, {});
    if (!scene) {
        if (scene.error().message.empty())
            std::abort();
        return 0;
    }
    // Long scenes are read, not played: the frames' cost is the benchmark's business.
    if (scene->last_frame > 500)
        return 0;
    const apcs::SceneAnimation animation(*scene, {});
    for (int f = 0; f <= animation.last_frame(); ++f)
        for (const apcs::Vec3& point : animation.frame(f))
            if (!std::isfinite(point.x) || !std::isfinite(point.y) || !std::isfinite(point.z))
                std::abort();
    return 0;
}
