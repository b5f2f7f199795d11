// A scene file's JOINT and RIGID lines (SPEC §8.1).
#include "scene_parser.h"
#include "apcs/scene/rigid_turn.h"
#include "scene_numbers.h"

#include "apcs/formats/number_text.h"

namespace apcs::scene_parsing {

Expected<void> SceneParser::parse_joint(const Fields& fields)
{
    if (fields.size() != 3 && fields.size() != 5)
        return error("expected 'JOINT NAME INDEX[-INDEX2] [TOLERANCE D]'");
    SceneJoint joint;
    joint.name = std::string(fields[1]);
    joint.line = m_line;
    // INDEX, or INDEX-INDEX2: the centroid of a contact region of points.
    const std::string_view range = fields[2];
    const std::size_t dash = range.find('-', 1);
    const std::optional<std::size_t> index = parse_count_value(range.substr(0, dash));
    const std::optional<std::size_t> last =
        dash == std::string_view::npos ? index : parse_count_value(range.substr(dash + 1));
    // No drawing has more points than a .dat file holds: a larger index is named as it was written.
    const auto valid = [](const std::optional<std::size_t>& value) { return value && *value >= 1 && *value <= max_dat_points; };
    if (!valid(index) || !valid(last))
        return error("expected the joint's point INDEX or points INDEX-INDEX2, whole numbers from 1 to " +
                     std::to_string(max_dat_points) + ", found " + quote_field(range));
    if (*last < *index)
        return error("joint points " + quote_field(range) + " run backwards; expected INDEX-INDEX2 with INDEX <= INDEX2");
    joint.point = *index - 1;
    joint.last_point = *last - 1;
    if (fields.size() == 5) {
        if (!equals_ignoring_case(fields[3], "TOLERANCE"))
            return error("expected TOLERANCE D after the index, found " + quote_field(fields[3]));
        const Expected<double> tolerance = number(fields[4], "TOLERANCE");
        if (!tolerance)
            return tolerance.error();
        if (*tolerance < 0.0)
            return error("TOLERANCE " + quote_field(fields[4]) + " is negative; expected a distance >= 0");
        joint.tolerance = *tolerance;
    }
    for (const SceneJoint& other : object().joints)
        if (other.name == joint.name)
            return error("joint " + quote_field(joint.name) + " is named twice in object '" + object().name +
                         "' (line " + std::to_string(other.line) + "); a joint joins two parts, each naming it once");
    object().joints.push_back(std::move(joint));
    return ok;
}

Expected<void> SceneParser::parse_rigid(const Fields& fields)
{
    if (fields.size() != 1)
        return error("expected 'RIGID' alone on its line, found " + quote_field(fields[1]) + " after it");
    if (Expected<void> first = once(object().rigid(), "RIGID"); !first)
        return first;
    object().rigid_line = m_line;
    return ok;
}

// A RIGID part turns from its KEY1 drawing to its KEY2 drawing: it needs both, congruent.
Expected<void> SceneParser::finish_rigid()
{
    const SceneObject& current = object();
    if (!current.rigid())
        return ok;
    if (!current.keys)
        return error("RIGID part '" + current.name +
                         "' has no KEYS; expected KEYS KEY1.dat KEY2.dat, the two poses it turns between",
                     current.rigid_line);
    const EqualisedKeys& keys = current.keys->keys;
    const RigidTurn turn = fit_rigid_turn(keys.key1.all_points(), keys.key2.all_points());
    // A part of no size (every point at one place) is allowed 0: the round-off of its coordinates,
    // not the drawing, decided (4.6e-16 off refused it).
    const double allowed = rigid_congruence * turn.size;
    double largest = 0.0;
    for (const Graphic* key : {&keys.key1, &keys.key2})
        for (const GraphicPart& part : key->parts)
            for (const Vec3& point : part.points)
                largest = std::max(largest, largest_coordinate(point));
    if (at_most_within_round_off(turn.worst_deviation, allowed, largest))
        return ok;
    return error("RIGID part '" + current.name + "': its KEY2 drawing is not its KEY1 drawing turned and moved: point " +
                     std::to_string(turn.worst_point + 1) + " is " + significant_number(turn.worst_deviation) +
                     " off; expected within 1e-4 of its size (" + significant_number(turn.size) + ")",
                 current.rigid_line);
}

} // namespace apcs::scene_parsing
