#include "apcs/animation/add_points.h"

#include <algorithm>
#include <utility>

namespace apcs {

std::vector<Vec3> add_points(std::span<const Vec3> polyline, std::size_t target_count)
{
    std::vector<Vec3> result(polyline.begin(), polyline.end());
    if (polyline.empty() || polyline.size() >= target_count)
        return result;
    if (polyline.size() == 1) {
        result.resize(target_count, polyline.front());
        return result;
    }
    const std::size_t segments = polyline.size() - 1;
    const std::size_t per_segment = (target_count - 1) / segments;    // RT
    const std::size_t with_one_more = (target_count - 1) % segments;  // RS
    result.clear();
    result.reserve(target_count);
    for (std::size_t s = 0; s < segments; ++s) {
        const std::size_t added = s < with_one_more ? per_segment : per_segment - 1;
        result.push_back(polyline[s]);
        for (std::size_t m = 1; m <= added; ++m)
            result.push_back(lerp(polyline[s], polyline[s + 1], static_cast<double>(m) / static_cast<double>(added + 1)));
    }
    result.push_back(polyline.back());
    return result;
}

PartSplitPlan plan_part_split(std::size_t larger_part_count, std::size_t smaller_part_count)
{
    if (smaller_part_count == 0)
        return {};
    return {larger_part_count % smaller_part_count, larger_part_count / smaller_part_count + 1,
            larger_part_count / smaller_part_count};
}

std::vector<GraphicPart> split_part(const GraphicPart& part, std::size_t pieces)
{
    if (pieces <= 1)
        return {part};
    const std::vector<Vec3> points = add_points(part.points, pieces + 1);
    const std::size_t segments = points.size() - 1;
    std::vector<GraphicPart> result;
    result.reserve(pieces);
    for (std::size_t j = 0; j < pieces; ++j) {
        const std::size_t first = j * segments / pieces;
        const std::size_t last = (j + 1) * segments / pieces;
        GraphicPart piece{part.name + "." + std::to_string(j + 1), Closure::open, {}};
        piece.points.assign(points.begin() + static_cast<std::ptrdiff_t>(first),
                            points.begin() + static_cast<std::ptrdiff_t>(last) + 1);
        result.push_back(std::move(piece));
    }
    return result;
}

namespace {

// Algorithm 1 applied to the graphic with fewer parts.
Graphic split_to_part_count(const Graphic& graphic, std::size_t part_count)
{
    const PartSplitPlan plan = plan_part_split(part_count, graphic.parts.size());
    Graphic result;
    result.parts.reserve(part_count);
    for (std::size_t i = 0; i < graphic.parts.size(); ++i) {
        const std::size_t pieces = i < plan.split_more ? plan.more_pieces : plan.fewer_pieces;
        for (GraphicPart& piece : split_part(graphic.parts[i], pieces))
            result.parts.push_back(std::move(piece));
    }
    return result;
}

} // namespace

EqualisedKeys equalise_key_frames(Graphic key1, Graphic key2)
{
    EqualisedKeys keys{std::move(key1), std::move(key2)};
    if (keys.key1.parts.empty() || keys.key2.parts.empty())
        return keys;
    if (keys.key1.parts.size() > keys.key2.parts.size())
        keys.key2 = split_to_part_count(keys.key2, keys.key1.parts.size());
    else if (keys.key2.parts.size() > keys.key1.parts.size())
        keys.key1 = split_to_part_count(keys.key1, keys.key2.parts.size());
    for (std::size_t i = 0; i < keys.key1.parts.size(); ++i) {
        std::vector<Vec3>& first = keys.key1.parts[i].points;
        std::vector<Vec3>& second = keys.key2.parts[i].points;
        if (first.size() > second.size())
            second = add_points(second, first.size());
        else if (second.size() > first.size())
            first = add_points(first, second.size());
    }
    return keys;
}

} // namespace apcs
