#include "apcs/scene/scene_joints.h"

namespace apcs {

std::string joint_points_text(std::size_t first, std::size_t last)
{
    return first == last ? "point " + std::to_string(first + 1)
                         : "points " + std::to_string(first + 1) + "-" + std::to_string(last + 1);
}

std::optional<JointEnds> find_joint(const Scene& scene, std::string_view name)
{
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& part = scene.objects[i];
        if (!part.parent)
            continue;
        for (const SceneJoint& joint : part.joints) {
            if (joint.name != name)
                continue;
            for (const SceneJoint& partner : scene.objects[*part.parent].joints)
                if (partner.name == name)
                    return JointEnds{i, joint.point, joint.last_point, *part.parent, partner.point, partner.last_point};
        }
    }
    return std::nullopt;
}

} // namespace apcs
