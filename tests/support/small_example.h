#pragma once

#include "support/temp_folder.h"

namespace apcs::test {

// The N-to-L example made small: KEY1 an N of 4 points, KEY2 an L of 3 (so KEY2 gains a point),
// and the two paths, in `folder`.
inline void write_small_example(const TempFolder& folder)
{
    folder.write("key1.dat", "0 0 0\n0 0 10\n0 6 0\n0 6 10\n");
    folder.write("key2.dat", "0 0 10\n0 0 0\n0 5 0\n");
    folder.write("way1.dat", "0 0 0\n3 -4 5\n0 0 10\n");
    folder.write("way4.dat", "0 6 10\n-3 10 5\n0 5 0\n");
}

} // namespace apcs::test
