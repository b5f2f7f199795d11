#pragma once

// Any bytes as a .scn file whose .dat files are a few small ones held in memory (any other name is
// missing): shared by the libFuzzer harness and the Catch test that replays its corpus.

#include "apcs/formats/dat_file.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"
#include "apcs/scene/scene_joints.h"

#include <cmath>
#include <map>
#include <string>
#include <string_view>

namespace apcs::fuzzing {

enum class SceneOutcome { refused, played, read_not_played, broken };

inline SceneOutcome read_and_play_scene(std::string_view text)
{
    static const std::map<std::string, std::string> dat_files{
        {"a.dat", "PART sq CLOSED\n0 0 0\n0 1 0\n0 1 1\n0 0 1\n"},
        {"b.dat", "0 0 0\n0 1 0\n"},
        {"c.dat", "0 0 2\n0 1 2\n0 2 2\n"},
        {"p.dat", "0 0 0\n0 5 1\n0 10 0\n"},
        {"q.dat", "0 0 0 0.5 0 0 1\n0 3 0 0 0 0 -1\n"},
        {"t.dat", "0 0 0\n0 1e-300 0\n"}, // a path too short for ALIGN's direction
    };
    const SceneFileReader read = [](const std::string& name) -> Expected<DatFile> {
        const auto found = dat_files.find(name);
        if (found == dat_files.end())
            return Diagnostic{name, 0, "no such file"};
        return parse_dat(found->second, name, 1);
    };
    const Expected<Scene> scene = parse_scene(text, "fuzz.scn", read, {});
    if (!scene)
        return scene.error().message.empty() ? SceneOutcome::broken : SceneOutcome::refused;
    // Long scenes are read, not played: the frames' cost is the benchmark's business.
    if (scene->last_frame > 500)
        return SceneOutcome::read_not_played;
    // Played as apcs play plays it without options: its SPACING line's spacing, else nearest.
    const SceneAnimation animation(*scene, scene_path_settings(*scene, {}, false));
    // What apcs play refuses (composed transforms past what a frame file holds) is a refusal; a
    // frame that passed that check must read back: finite and within the .dat files' 1e9.
    if (animation.first_out_of_reach(max_dat_magnitude))
        return SceneOutcome::refused;
    // So is a joint closing a cycle of joints that a KEYS drawing pulls open in some frame.
    if (const Expected<void> closed = check_closing_joints(*scene, animation, "fuzz.scn"); !closed)
        return closed.error().message.empty() ? SceneOutcome::broken : SceneOutcome::refused;
    const auto readable = [](double value) { return std::isfinite(value) && std::abs(value) <= max_dat_magnitude; };
    for (int f = 0; f <= animation.last_frame(); ++f)
        for (const Vec3& point : animation.frame(f))
            if (!readable(point.x) || !readable(point.y) || !readable(point.z))
                return SceneOutcome::broken;
    return SceneOutcome::played;
}

} // namespace apcs::fuzzing
