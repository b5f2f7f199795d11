#include "apcs/animation/path_change.h"

#include <algorithm>

namespace apcs {

PathChange combined(const PathChange& earlier, const PathChange& later)
{
    // Both ranges in the points between the changes: what `earlier` inserted, what `later` removed.
    const std::size_t first = std::min(earlier.first, later.first);
    const std::size_t end_between = std::max(earlier.first + earlier.inserted, later.first + later.removed);
    // The end lies past both ranges, so it moves with the points after each.
    const std::size_t end_before = end_between - earlier.inserted + earlier.removed;
    const std::size_t end_after = end_between - later.removed + later.inserted;
    return {first, end_before - first, end_after - first, std::max(earlier.what, later.what)};
}

} // namespace apcs
