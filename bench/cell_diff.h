#pragma once

#include "apcs/raster/cell_grid.h"

#include <cstddef>

namespace apcs::bench {

// The cells a screen update would send: what the terminal layer diffs before it writes.
inline std::size_t changed_cells(const CellGrid& before, const CellGrid& after)
{
    std::size_t changed = 0;
    for (int row = 0; row < after.rows(); ++row)
        for (int column = 0; column < after.columns(); ++column)
            changed += before.at(column, row) != after.at(column, row) ? 1u : 0u;
    return changed;
}

} // namespace apcs::bench
