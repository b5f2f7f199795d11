#include "apcs/animation/memory_budget.h"

#include "apcs/animation/arc_length.h"
#include "apcs/animation/motion_path.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <limits>
#include <string>

namespace apcs::memory {

static_assert(bytes_per_printed_sample >= sizeof(Vec3));
static_assert(bytes_per_control_point >=
              sizeof(ControlPoint) + 2 * sizeof(HermiteSegment) + sizeof(int) + sizeof(double) +
                  sizeof(AccelerationSpan) + 2 * sizeof(double) + 8);
static_assert(bytes_per_inbetween >= sizeof(Inbetween) + sizeof(double));
static_assert(bytes_per_frame_point >= sizeof(Vec3));

namespace {

constexpr std::uint64_t saturated = std::numeric_limits<std::uint64_t>::max();

std::uint64_t saturating_product(std::uint64_t left, std::uint64_t right)
{
    std::uint64_t product = 0;
    return __builtin_mul_overflow(left, right, &product) ? saturated : product;
}

constexpr std::array<std::string_view, 5> unit_names{"bytes", "KiB", "MiB", "GiB", "TiB"};

} // namespace

std::uint64_t saturating_sum(std::uint64_t left, std::uint64_t right)
{
    return left > saturated - right ? saturated : left + right;
}

std::uint64_t path_bytes(const PathRequest& request)
{
    const std::uint64_t segments = request.control_points > 1 ? request.control_points - 1 : 0;
    const std::uint64_t samples =
        saturating_sum(saturating_product(segments, static_cast<std::uint64_t>(std::max(request.samples_per_segment, 1))), 1);
    const std::uint64_t printed = request.printed ? bytes_per_printed_point : 0;
    const std::uint64_t printed_sample = request.printed ? bytes_per_printed_sample + printed : 0;
    const std::uint64_t inbetweens = static_cast<std::uint64_t>(std::max(request.inbetween_count, 0));
    return saturating_sum(saturating_sum(saturating_product(samples, printed_sample),
                                         saturating_product(inbetweens, bytes_per_inbetween + printed)),
                          saturating_product(request.control_points, bytes_per_control_point));
}

std::uint64_t frames_bytes(const FramesRequest& request)
{
    const std::uint64_t per_point = bytes_per_frame_point + (request.printed ? bytes_per_printed_point : 0);
    return saturating_sum(saturating_product(saturating_product(request.frame_count, request.points_per_frame), per_point),
                          saturating_product(request.points_per_frame, bytes_per_key_point));
}

std::string describe(const PathRequest& request)
{
    return std::to_string(request.control_points) + " control points x " + std::to_string(request.samples_per_segment) +
           " samples per segment (--samples) and " + std::to_string(request.inbetween_count) +
           " in-betweens (--inbetweens)";
}

std::string describe(const FramesRequest& request)
{
    return std::to_string(request.frame_count) + " frames of " + std::to_string(request.points_per_frame) + " points";
}

std::optional<std::uint64_t> parse_byte_count(std::string_view text)
{
    std::size_t digits = 0;
    std::uint64_t count = 0;
    for (; digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits])) != 0; ++digits)
        if (__builtin_mul_overflow(count, 10u, &count) || __builtin_add_overflow(count, static_cast<unsigned>(text[digits] - '0'), &count))
            return std::nullopt;
    if (digits == 0)
        return std::nullopt;
    std::string suffix;
    for (const char c : text.substr(digits))
        suffix += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    std::uint64_t unit = 1;
    if (!suffix.empty()) {
        const std::size_t power = std::string_view("KMGT").find(suffix[0]);
        const std::string_view rest = std::string_view(suffix).substr(1);
        if (power == std::string_view::npos || !(rest.empty() || rest == "B" || rest == "IB"))
            return std::nullopt;
        unit = 1ull << (10 * (power + 1));
    }
    std::uint64_t bytes = 0;
    if (count == 0 || __builtin_mul_overflow(count, unit, &bytes))
        return std::nullopt;
    return bytes;
}

std::string byte_count_text(std::uint64_t bytes)
{
    std::size_t unit = 0;
    double amount = static_cast<double>(bytes);
    while (amount >= 1024.0 && unit + 1 < unit_names.size()) {
        amount /= 1024.0;
        ++unit;
    }
    if (unit == 0)
        return std::to_string(bytes) + " bytes";
    char text[32];
    std::snprintf(text, sizeof text, amount == static_cast<double>(static_cast<std::uint64_t>(amount)) ? "%.0f" : "%.1f", amount);
    return std::string(text) + " " + std::string(unit_names[unit]);
}

Expected<void> check_fits(std::string_view what, std::uint64_t needed, std::uint64_t limit, std::string_view remedy)
{
    if (needed <= limit)
        return ok;
    return Diagnostic{"apcs", 0,
                      std::string(what) + " need " + byte_count_text(needed) + "; the memory limit is " +
                          byte_count_text(limit) + " (" + std::string(limit_variable) + "); " + std::string(remedy)};
}

} // namespace apcs::memory
