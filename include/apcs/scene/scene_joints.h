#pragma once

#include "apcs/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

// A joint's two ends (thesis Ch. 3.3's key point): a point of a part's drawing and a point of its
// parent's, which every frame keeps within the joint's tolerance.
struct JointEnds {
    std::size_t part = 0; // object indices in Scene::objects
    std::size_t part_point = 0; // the first of its points; part_last the last (a contact region)
    std::size_t part_last = 0;
    std::size_t parent = 0;
    std::size_t parent_point = 0;
    std::size_t parent_last = 0;
};

// A joint's points as the .scn file numbers them (from 1): "point 7", or "points 3-5" for a
// contact region of points first … last (0-based).
std::string joint_points_text(std::size_t first, std::size_t last);

// The joint called `name` in a checked scene; none when no part declares it.
std::optional<JointEnds> find_joint(const Scene& scene, std::string_view name);

} // namespace apcs
