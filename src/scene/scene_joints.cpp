#include "apcs/scene/scene_joints.h"

#include "apcs/formats/number_text.h"
#include "apcs/formats/path_files.h"
#include "apcs/formats/text_fields.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"
#include "scene_numbers.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <utility>
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

double joint_tolerance(const Scene& scene, const JointUse& a, const JointUse& b, double default_tolerance)
{
    return joint_of(scene, b).tolerance.value_or(joint_of(scene, a).tolerance.value_or(default_tolerance));
}

// A joint's two places at one frame, and how far apart they may be.
struct JointGap {
    JointUse earlier;
    JointUse later;
    Vec3 at_earlier;
    Vec3 at_later;
    int frame = 0;
    double tolerance = 0.0;

    // Within the tolerance, the coordinates' round-off forgiven: a joint drawn exactly TOLERANCE
    // apart (0.4 - 0.1 is 0.30000000000000004) is closed.
    bool closed() const
    {
        return at_most_within_round_off(distance(at_earlier, at_later), tolerance,
                                        std::max(largest_coordinate(at_earlier), largest_coordinate(at_later)));
    }
};

// "joint 'j': point 1 of 'a' (line 4) (0, 0, 0) and point 2 of 'b' (0, 1, 0) are 1 apart in frame 0;
// expected at most 0.001" and `why`.
std::string gap_message(const Scene& scene, const std::string& name, const JointGap& gap, const std::string& why)
{
    const SceneJoint& first = joint_of(scene, gap.earlier);
    const SceneJoint& second = joint_of(scene, gap.later);
    const auto [apart, allowed] = significant_numbers(distance(gap.at_earlier, gap.at_later), gap.tolerance);
    return "joint " + quote_field(name) + ": " + joint_points_text(first.point, first.last_point) + " of '" +
           scene.objects[gap.earlier.object].name + "' (line " + std::to_string(first.line) + ") " +
           describe_point(gap.at_earlier) + " and " + joint_points_text(second.point, second.last_point) + " of '" +
           scene.objects[gap.later.object].name + "' " + describe_point(gap.at_later) + " are " + apart +
           " apart in frame " + std::to_string(gap.frame) + "; expected at most " + allowed + why;
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
    if (first.tolerance && second.tolerance && *first.tolerance != *second.tolerance) {
        const auto [here, there] = significant_numbers(*second.tolerance, *first.tolerance);
        return error("joint " + quote_field(name) + " has TOLERANCE " + here + " here and " + there + " on line " +
                         std::to_string(first.line) + "; expected one value (or the same on both lines)",
                     second.line);
    }
    const JointGap gap{list[0], list[1], place_in_frame_0(scene, list[0]), place_in_frame_0(scene, list[1]), 0,
                       joint_tolerance(scene, list[0], list[1], default_tolerance)};
    if (gap.closed())
        return ok;
    return error(gap_message(scene, name, gap, ""), second.line);
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

Expected<void> check_closing_joints(const Scene& scene, const SceneAnimation& animation, const std::string& file_name)
{
    // A joint no part is anchored at closes a cycle of joints (A to B, B to C, C back to A): frame
    // 0 was checked with the drawings, but nothing moves a part to keep it in the other frames.
    const double default_tolerance = default_joint_tolerance(scene);
    std::vector<std::pair<std::string, JointGap>> closing;
    for (const auto& [name, list] : joint_uses(scene)) {
        const std::optional<SceneAnchor>& anchor = scene.objects[list.back().object].anchor;
        if (list.size() != 2 || (anchor && anchor->joint == list[1].joint))
            continue;
        closing.push_back({name, JointGap{list[0], list[1], {}, {}, 0,
                                          joint_tolerance(scene, list[0], list[1], default_tolerance)}});
    }
    if (closing.empty())
        return ok;
    std::vector<Vec3> points(animation.points_per_frame());
    const auto place = [&](const JointUse& use) {
        const ObjectPoints at = animation.object_points()[use.object];
        const SceneJoint& joint = joint_of(scene, use);
        return joint_place(std::span<const Vec3>(points).subspan(at.first, at.count), joint.point, joint.last_point);
    };
    for (int f = 0; f <= animation.last_frame(); ++f) {
        animation.frame(f, points);
        for (auto& [name, gap] : closing) {
            gap.at_earlier = place(gap.earlier);
            gap.at_later = place(gap.later);
            gap.frame = f;
            if (!gap.closed())
                return Diagnostic{file_name, joint_of(scene, gap.later).line,
                                  gap_message(scene, name, gap,
                                              " (the joint closes a cycle of joints: no part is moved to keep it)")};
        }
    }
    return ok;
}

} // namespace apcs
