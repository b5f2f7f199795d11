#include "apcs/scene/scene_joints.h"

#include "apcs/formats/number_text.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/text_fields.h"
#include "apcs/scene/scene_file.h"

#include <map>
#include <vector>

namespace apcs {

namespace {

struct JointUse {
    std::size_t object;
    std::size_t joint; // index in the object's joints
};

const SceneJoint& joint_of(const Scene& scene, const JointUse& use) { return scene.objects[use.object].joints[use.joint]; }

Vec3 place_in_frame_0(const Scene& scene, const JointUse& use)
{
    const SceneJoint& joint = joint_of(scene, use);
    return joint_place(scene.objects[use.object].first_drawing()->all_points(), joint.point, joint.last_point);
}

// Every joint name with its uses, in file order.
std::map<std::string, std::vector<JointUse>> joint_uses(const Scene& scene)
{
    std::map<std::string, std::vector<JointUse>> uses;
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        for (std::size_t j = 0; j < scene.objects[i].joints.size(); ++j)
            uses[scene.objects[i].joints[j].name].push_back({i, j});
    return uses;
}

// A joint's two uses: two parts of one object, one TOLERANCE, their points met in frame 0.
Expected<void> check_joint(const Scene& scene, const std::string& file_name, const std::string& name,
                           const std::vector<JointUse>& list, double default_tolerance)
{
    const auto error = [&](std::string message, int line) { return Diagnostic{file_name, line, std::move(message)}; };
    if (list.size() != 2)
        return error("joint " + quote_field(name) + " is used " + std::to_string(list.size()) +
                         " time(s); expected exactly twice, in two parts of one object",
                     joint_of(scene, list.back()).line);
    const SceneJoint& first = joint_of(scene, list[0]);
    const SceneJoint& second = joint_of(scene, list[1]);
    const SceneObject& a = scene.objects[list[0].object];
    const SceneObject& b = scene.objects[list[1].object];
    const std::size_t root_a = root_object(scene, list[0].object);
    const std::size_t root_b = root_object(scene, list[1].object);
    if (root_a != root_b)
        return error("joint " + quote_field(name) + " joins '" + a.name + "' (line " + std::to_string(first.line) +
                         ") of object '" + scene.objects[root_a].name + "' and '" + b.name + "' of object '" +
                         scene.objects[root_b].name + "'; expected two parts of one object",
                     second.line);
    // Two different values would leave one silently unused.
    if (first.tolerance && second.tolerance && *first.tolerance != *second.tolerance)
        return error("joint " + quote_field(name) + " has TOLERANCE " + shortest_number(*second.tolerance) +
                         " here and " + shortest_number(*first.tolerance) + " on line " + std::to_string(first.line) +
                         "; expected one value (or the same on both lines)",
                     second.line);
    const Vec3 pa = place_in_frame_0(scene, list[0]);
    const Vec3 pb = place_in_frame_0(scene, list[1]);
    const double tolerance = second.tolerance.value_or(first.tolerance.value_or(default_tolerance));
    if (distance(pa, pb) <= tolerance)
        return ok;
    return error("joint " + quote_field(name) + ": " + joint_points_text(first.point, first.last_point) + " of '" + a.name +
                     "' (line " + std::to_string(first.line) + ") " + describe_point(pa) + " and " +
                     joint_points_text(second.point, second.last_point) + " of '" + b.name + "' " + describe_point(pb) +
                     " are " + shortest_number(distance(pa, pb)) + " apart in frame 0; expected at most " +
                     shortest_number(tolerance),
                 second.line);
}

// Each part's anchor: its first joint, in its own lines' order, shared with a part declared before it.
void set_anchors(Scene& scene, const std::map<std::string, std::vector<JointUse>>& uses)
{
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        SceneObject& part = scene.objects[i];
        for (std::size_t j = 0; j < part.joints.size() && !part.anchor; ++j) {
            const JointUse& earlier = uses.at(part.joints[j].name).front();
            if (earlier.object < i)
                part.anchor = SceneAnchor{j, earlier.object, earlier.joint};
        }
    }
}

} // namespace

std::string joint_points_text(std::size_t first, std::size_t last)
{
    return first == last ? "point " + std::to_string(first + 1)
                         : "points " + std::to_string(first + 1) + "-" + std::to_string(last + 1);
}

std::optional<JointEnds> find_joint(const Scene& scene, std::string_view name)
{
    std::vector<JointEnd> ends;
    for (std::size_t i = 0; i < scene.objects.size() && ends.size() < 2; ++i)
        for (const SceneJoint& joint : scene.objects[i].joints)
            if (joint.name == name)
                ends.push_back({i, joint.point, joint.last_point});
    if (ends.size() != 2)
        return std::nullopt;
    return JointEnds{ends[0], ends[1]};
}

std::size_t root_object(const Scene& scene, std::size_t index)
{
    while (scene.objects[index].parent)
        index = *scene.objects[index].parent;
    return index;
}

Expected<void> connect_joints(Scene& scene, const std::string& file_name)
{
    const std::map<std::string, std::vector<JointUse>> uses = joint_uses(scene);
    const double default_tolerance = default_joint_tolerance(scene);
    for (const auto& [name, list] : uses)
        if (Expected<void> joint = check_joint(scene, file_name, name, list, default_tolerance); !joint)
            return joint;
    set_anchors(scene, uses);
    for (const SceneObject& part : scene.objects)
        if (part.rigid() && !part.anchor)
            return Diagnostic{file_name, part.rigid_line,
                              "RIGID part '" + part.name +
                                  "' has no anchor: none of its joints is shared with a part declared before it; "
                                  "expected a JOINT with an earlier part (the joint it turns about)"};
    return ok;
}

} // namespace apcs
