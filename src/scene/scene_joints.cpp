#include "apcs/scene/scene_joints.h"

namespace apcs {

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
