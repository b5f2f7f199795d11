// libFuzzer harness: the session state machine fed random key streams over the N to L example
// kept in memory. It must never crash or hang, and every file it writes must be a plain name in
// its folder.
#include "session_keystrokes.h"

#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (!apcs::fuzzing::writes_stay_in_folder(apcs::fuzzing::play_keystrokes({data, size})))
        std::abort();
    return 0;
}
