#pragma once

#include "apcs/scene/scene.h"

#include <string>

namespace apcs {

// The scene as the thesis' data structure (figs. 3.3.1–3.3.2): one node per object, indented under
// its parent, with its four-line values t c b a, its number of parts N (0: a leaf, "a single
// object"), its drawing, behaviours and key points. `scene_name` heads it.
std::string format_scene_tree(const Scene& scene, const std::string& scene_name);

} // namespace apcs
