#include "apcs/scene/scene_tree.h"

#include "apcs/formats/number_text.h"

#include <vector>

namespace apcs {

namespace {

std::string node_line(const Scene& scene, std::size_t index, std::size_t parts)
{
    const SceneObject& object = scene.objects[index];
    std::string line = object.name + "  t c b a " + format_staff_value(object.staff.tension) + " " +
                       format_staff_value(object.staff.continuity) + " " + format_staff_value(object.staff.bias) + " " +
                       format_staff_value(object.staff.acceleration) + (object.own_staff ? "" : " (inherited)") +
                       "  N=" + std::to_string(parts);
    if (object.shape)
        line += "  SHAPE " + std::to_string(object.shape->point_count()) + " points";
    if (object.keys)
        line += "  KEYS " + std::to_string(object.keys->keys.key1.point_count()) + " points, frames " +
                std::to_string(object.keys->frames.from) + "-" + std::to_string(object.keys->frames.to);
    if (object.move)
        line += std::string("  MOVE") + (object.move->times.empty() ? "" : " TIMES") + (object.move->loop ? " LOOP" : "");
    if (object.rotate)
        line += "  ROTATE " + shortest_number(object.rotate->degrees_per_frame);
    if (object.roll)
        line += "  ROLL " + shortest_number(object.roll->radius);
    if (object.scale) {
        const Vec3& factors = object.scale->factors;
        line += "  SCALE " + shortest_number(factors.x);
        if (factors.y != factors.x || factors.z != factors.x)
            line += " " + shortest_number(factors.y) + " " + shortest_number(factors.z);
    }
    for (const SceneJoint& joint : object.joints)
        line += "  JOINT " + joint.name;
    if (object.rigid())
        line += "  RIGID";
    if (object.anchor)
        line += "  anchor " + object.joints[object.anchor->joint].name + " on " + scene.objects[object.anchor->partner].name;
    return line;
}

// Past this many levels the tree is indented no further, each deeper node saying its depth
// instead: a 10,000-deep chain indented all the way printed 200 MB.
constexpr std::size_t most_indented_levels = 32;

void append_subtree(std::string& text, const Scene& scene, const std::vector<std::vector<std::size_t>>& children,
                    std::size_t index, const std::string& indent, bool last, std::size_t depth)
{
    const std::string depth_mark = depth > most_indented_levels ? "(depth " + std::to_string(depth) + ") " : "";
    text += indent + (last ? "`-- " : "|-- ") + depth_mark + node_line(scene, index, children[index].size()) + "\n";
    const std::string deeper = depth >= most_indented_levels ? indent : indent + (last ? "    " : "|   ");
    for (std::size_t k = 0; k < children[index].size(); ++k)
        append_subtree(text, scene, children, children[index][k], deeper, k + 1 == children[index].size(), depth + 1);
}

} // namespace

std::string format_scene_tree(const Scene& scene, const std::string& scene_name)
{
    std::vector<std::vector<std::size_t>> children(scene.objects.size());
    std::vector<std::size_t> roots;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        (scene.objects[i].parent ? children[*scene.objects[i].parent] : roots).push_back(i);
    std::string text = scene_name + ": frames 0-" + std::to_string(scene.last_frame) + ", " +
                       std::to_string(scene.objects.size()) + " objects\n";
    for (std::size_t k = 0; k < roots.size(); ++k)
        append_subtree(text, scene, children, roots[k], "", k + 1 == roots.size(), 1);
    return text;
}

} // namespace apcs
