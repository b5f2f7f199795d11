#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

class SceneAnimation;

// One end of a joint: points first … last (0-based; a contact region when they differ) of a part.
struct JointEnd {
    std::size_t object = 0; // index in Scene::objects
    std::size_t first = 0;
    std::size_t last = 0;
};

// A joint's two ends (thesis Ch. 3.3's key point), the part declared first as `earlier`: every
// frame keeps them within the joint's tolerance.
struct JointEnds {
    JointEnd earlier;
    JointEnd later;
};

// A joint's points as the .scn file numbers them (from 1): "point 7", or "points 3-5" for a
// contact region of points first … last (0-based).
std::string joint_points_text(std::size_t first, std::size_t last);

// The joint called `name` in a checked scene; none when no part declares it.
std::optional<JointEnds> find_joint(const Scene& scene, std::string_view name);

// The object a part belongs to: the root of its PARENT chain.
std::size_t root_object(const Scene& scene, std::size_t index);

// Checks a scene's joints as a graph (SPEC §8.2) and sets each part's anchor: every joint name is
// used by exactly two parts of one object, with one TOLERANCE at most, its two points within it in
// frame 0; every RIGID part has an anchor. `file_name` names the scene in the diagnostic.
Expected<void> connect_joints(Scene& scene, const std::string& file_name);

// The joints that are no part's anchor, each closing a cycle of joints (A to B, B to C, C back to
// A), checked in every frame of `animation`: nothing moves a part to keep them, so a KEYS drawing
// may pull one open. The first frame, in it the first joint by name, more than its tolerance open
// is "FILE:LINE: joint ... apart in frame F ...", LINE its later JOINT line.
Expected<void> check_closing_joints(const Scene& scene, const SceneAnimation& animation, const std::string& file_name);

} // namespace apcs
