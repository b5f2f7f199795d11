#pragma once

#include "apcs/base/diagnostic.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

// How much memory a request will take, estimated before anything is allocated, and the budget it
// must fit in: a request over the budget is refused with a message instead of ending in an
// allocation failure half-way (SPEC §1). The estimates are generous on purpose: they count every
// copy a command holds at once, so a request they accept does not run out of memory later.
namespace apcs::memory {

// The budget unless the environment variable APCS_MEMORY_LIMIT gives another.
inline constexpr std::uint64_t default_limit_bytes = 4ull << 30;
inline constexpr std::string_view limit_variable = "APCS_MEMORY_LIMIT";

// What one element of a request costs, in bytes; memory_budget.cpp checks each against the sizes
// of the types it stands for.
// A curve sample takes no memory: samples are computed when needed (sampled_curve.h). Printed, each
// is held, and its text.
inline constexpr std::uint64_t bytes_per_printed_sample = 24;
// A control point: itself, its KB segment, its arc-length table entry, its acceleration span, its
// segment's lengths and its share of the drawn curve's block rasters (31320 bytes for 4096).
inline constexpr std::uint64_t bytes_per_control_point = 320;
// A shown in-between: its position, progress and sample, and its target distance.
inline constexpr std::uint64_t bytes_per_inbetween = 48;
// A point as printed text: "-1000000000.000000 " three times, the longest a coordinate prints.
inline constexpr std::uint64_t bytes_per_printed_point = 60;
// A point of a frame sequence.
inline constexpr std::uint64_t bytes_per_frame_point = 24;
// A point of the key frames: both keys, its place along the graphic, its blend weights, and the
// text of one frame for each of the up to 8 files written at once.
inline constexpr std::uint64_t bytes_per_key_point = 8 * bytes_per_printed_point + 128;

// One point's path (apcs path, the session's path editor): control points × samples per segment.
struct PathRequest {
    std::size_t control_points = 0;
    int samples_per_segment = 1;
    int inbetween_count = 0;
    bool printed = false; // the curve and in-betweens as text (--print)
};

// Frames of one graphic (surface fitting, apcs inbetween): frames × points.
struct FramesRequest {
    std::size_t frame_count = 0;
    std::size_t points_per_frame = 0;
    bool printed = false;
};

// "1000 control points × 100000 samples per segment (--samples) and 12 in-betweens (--inbetweens)".
std::string describe(const PathRequest& request);
// "100002 frames of 1000000 points".
std::string describe(const FramesRequest& request);

// Byte counts saturate at UINT64_MAX instead of wrapping.
std::uint64_t path_bytes(const PathRequest& request);
std::uint64_t frames_bytes(const FramesRequest& request);
std::uint64_t saturating_sum(std::uint64_t left, std::uint64_t right);

// "4294967296", "512K", "64M", "4G", "1T" (powers of 1024, either case, an optional B or iB after
// the letter: "4GiB"); nullopt for anything else, for 0 and for counts past UINT64_MAX.
std::optional<std::uint64_t> parse_byte_count(std::string_view text);

// "4 GiB", "1.5 MiB", "900 bytes": the unit that keeps the number below 1024, one decimal.
std::string byte_count_text(std::uint64_t bytes);

// ok when `needed` fits in `limit`; else the refusal, a diagnostic of the program itself ("apcs")
// whose message is "WHAT need 9.3 GiB; the memory limit is 4 GiB (APCS_MEMORY_LIMIT); REMEDY".
Expected<void> check_fits(std::string_view what, std::uint64_t needed, std::uint64_t limit, std::string_view remedy);

} // namespace apcs::memory
