#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/cli/options.h"
#include "apcs/base/exit_status.h"

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string_view>

namespace apcs {

// The memory budget of this run: options.memory_limit when set, else APCS_MEMORY_LIMIT when set
// (refused unless a byte count such as 4G), else memory::default_limit_bytes.
Expected<std::uint64_t> memory_limit(const CommonOptions& options);

// Nothing when `needed` bytes fit in the run's budget. Else the refusal is written to `err` as
// "apcs: WHAT need N; the memory limit is L (APCS_MEMORY_LIMIT); REMEDY" and its exit status
// returned (bad input; bad usage for an APCS_MEMORY_LIMIT that is no byte count).
std::optional<ExitStatus> refuse_over_budget(std::string_view what, std::uint64_t needed, const CommonOptions& options,
                                             std::string_view remedy, std::ostream& err);

} // namespace apcs
