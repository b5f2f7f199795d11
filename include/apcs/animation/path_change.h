#pragma once

#include <cstddef>
#include <vector>

namespace apcs {

// What a change did to a path's control points: points first … first + removed − 1 were replaced
// by first … first + inserted − 1 (a staff key: as many as it changed, by themselves; a waypoint
// moved: one by one; inserted: none by one; deleted: one by none). `what` says which of their
// values may differ: only accelerations (the in-betweens move, no segment), tension, continuity
// and bias too (the segments change, no point moves), or positions (points moved, inserted or
// deleted).
struct PathChange {
    enum class What { accelerations, staff, positions };
    std::size_t first = 0;
    std::size_t removed = 0;
    std::size_t inserted = 0;
    What what = What::positions;
};

// `earlier`, then `later` (in the points `earlier` left), as one change: the range covering both,
// from the points before `earlier` to those after `later`, with the larger `what`.
PathChange combined(const PathChange& earlier, const PathChange& later);

// When the work a change causes is done: all of it at once (scripts, tests, files), or the part a
// first picture needs at once and the rest (exact spacing's arc lengths, the in-betweens on them,
// the curve's pixels past a budget) in steps after it, while no key waits (the terminal).
enum class Refinement { at_once, in_steps };

// What a change did to a curve's segments: segments first … first + removed − 1 were replaced by
// first … first + inserted − 1, and those before and after are as they were (shifted by
// inserted − removed). A change of values only has removed == inserted; a control point inserted
// into a path replaces a few segments by one more. Whoever keeps something per segment (lengths,
// arc lengths, rasters) splices it alike and makes again only what the range covers.
struct SegmentSplice {
    std::size_t first = 0;
    std::size_t removed = 0;
    std::size_t inserted = 0;

    std::size_t old_end() const { return first + removed; }
    std::size_t new_end() const { return first + inserted; }
    // Where index `index` of the curve before the change stands after it; one inside the change
    // goes to the change's start (a range's first) or its end (a range's end).
    std::size_t moved(std::size_t index, bool is_end) const
    {
        if (index < first || (is_end && index == first))
            return index;
        if (index >= old_end())
            return index - removed + inserted;
        return is_end ? new_end() : first;
    }
    friend bool operator==(const SegmentSplice&, const SegmentSplice&) = default;
};

// Segments first … end − 1 (none when end ≤ first).
struct SegmentRange {
    std::size_t first = 0;
    std::size_t end = 0;

    bool empty() const { return end <= first; }
    std::size_t size() const { return empty() ? 0 : end - first; }
    bool meets(std::size_t from, std::size_t to) const { return !empty() && from < end && first < to; }
    friend bool operator==(const SegmentRange&, const SegmentRange&) = default;
};

// Per-segment `values` made to fit the curve after `change`: the entries of the segments after it
// move with them; those of the inserted segments are T{} until they are made.
template <typename T, typename Allocator>
void splice_room(std::vector<T, Allocator>& values, const SegmentSplice& change)
{
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(change.first);
    if (change.inserted > change.removed)
        values.insert(at, change.inserted - change.removed, T{});
    else
        values.erase(at, at + static_cast<std::ptrdiff_t>(change.removed - change.inserted));
}

} // namespace apcs
