#include "memory_limit.h"

#include "apcs/animation/memory_budget.h"

#include <cstdlib>
#include <ostream>
#include <string>

namespace apcs {

Expected<std::uint64_t> memory_limit(const CommonOptions& options)
{
    if (options.memory_limit)
        return *options.memory_limit;
    const std::string variable(memory::limit_variable);
    const char* value = std::getenv(variable.c_str());
    // Empty means unset, as for APCS_DATA: `APCS_MEMORY_LIMIT= apcs ...` takes the default.
    if (value == nullptr || *value == '\0')
        return memory::default_limit_bytes;
    if (const std::optional<std::uint64_t> bytes = memory::parse_byte_count(value))
        return *bytes;
    return Diagnostic{variable, 0,
                      "expected a byte count above 0 such as 4294967296, 512M or 4G; found '" + std::string(value) + "'"};
}

std::optional<ExitStatus> refuse_over_budget(std::string_view what, std::uint64_t needed, const CommonOptions& options,
                                             std::string_view remedy, std::ostream& err)
{
    const Expected<std::uint64_t> limit = memory_limit(options);
    if (!limit) {
        err << limit.error().to_string() << '\n';
        return ExitStatus::bad_usage;
    }
    if (const Expected<void> fits = memory::check_fits(what, needed, *limit, remedy); !fits) {
        err << fits.error().to_string() << '\n';
        return ExitStatus::bad_input;
    }
    return std::nullopt;
}

} // namespace apcs
