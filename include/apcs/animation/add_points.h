#pragma once

#include "apcs/animation/graphic.h"

#include <span>
#include <vector>

namespace apcs {

// Thesis Algorithm 2 (addpoint.c, SPEC §5.1): gives a polyline of NP2 points `target_count` points.
// With NP1 = target_count, RT = (NP1−1) div (NP2−1) and RS = (NP1−1) mod (NP2−1), the first RS
// segments each get RT new points and the others RT−1, placed evenly along the segment by linear
// interpolation; the original points stay, in order. A single point is repeated. A polyline that
// already has target_count points or more comes back unchanged.
std::vector<Vec3> add_points(std::span<const Vec3> polyline, std::size_t target_count);

// How Algorithm 1 splits the parts of the graphic with fewer parts (N2 of them) to reach N1:
// the first `split_more` parts into `more_pieces` each, the rest into `fewer_pieces` each, where
// A = N1 mod N2, B = N1 div N2 + 1, C = N1 div N2, so that A·B + (N2−A)·C = N1.
struct PartSplitPlan {
    std::size_t split_more = 0;   // A
    std::size_t more_pieces = 1;  // B
    std::size_t fewer_pieces = 1; // C
};
PartSplitPlan plan_part_split(std::size_t larger_part_count, std::size_t smaller_part_count);

// Splits a part into `pieces` parts that keep its points in order and share the cut points
// (piece j ends where piece j+1 starts). A part with fewer than pieces+1 points first gets points
// by Algorithm 2. Pieces are open and named "name.1", "name.2", …
std::vector<GraphicPart> split_part(const GraphicPart& part, std::size_t pieces);

struct EqualisedKeys {
    Graphic key1;
    Graphic key2;
};

// Gives both key frames the same parts and, part by part, the same point counts: Algorithm 1
// on the parts of whichever key has fewer, then Algorithm 2 on each pair of parts. The part names
// and closure of each key are kept where parts are not split.
// The keys are taken by value: callers that no longer need them move them in.
EqualisedKeys equalise_key_frames(Graphic key1, Graphic key2);

} // namespace apcs
