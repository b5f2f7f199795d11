// libFuzzer harness: any bytes as a .dat file. The reader must return a file or a diagnostic,
// never crash or hang; an accepted file must format and read back to the same point count.
#include "apcs/formats/dat_file.h"

#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const apcs::Expected<apcs::DatFile> file = apcs::parse_dat(text, "fuzz.dat", 0);
    if (file) {
        const std::string written = apcs::format_dat(*file);
        const apcs::Expected<apcs::DatFile> again = apcs::parse_dat(written, "again.dat", 0);
        if (!again || again->point_count() != file->point_count())
            std::abort();
    }
    return 0;
}
