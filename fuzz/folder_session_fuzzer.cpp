// libFuzzer harness: the session over a real folder of hostile entries (fuzz/hostile_folder.h).
// No special file, read-only file, key file or file outside the folder may change, no temporary
// file may stay behind, and a run must return (a FIFO opened for reading would hang it).
#include "hostile_folder.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const apcs::fuzzing::FolderRun run = apcs::fuzzing::play_in_hostile_folder({data, size});
    if (run.violation) {
        std::fprintf(stderr, "folder_session_fuzzer: %s\n", run.violation->c_str());
        std::abort();
    }
    return 0;
}
