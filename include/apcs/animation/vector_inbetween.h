#pragma once

#include "apcs/animation/frame_sequence.h"
#include "apcs/animation/speed_law.h"

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace apcs {

// How the graphic with fewer points is padded to the other's count (Luo, Sun, Zhang 2003; SPEC §6).
enum class Padding {
    apcs,     // thesis Algorithm 1 and 2 (points added evenly along segments)
    start,    // repeat P_1 in front
    end,      // repeat P_m at the end
    middle,   // repeat evenly chosen points once each, s_i = ⌈i·m/(n−m)⌉
    midpoint, // insert midpoints of evenly chosen segments (after P_s; at s = m, P_m itself)
};

std::optional<Padding> padding_from_name(std::string_view name);

// Pads `points` (m of them) to `target_count` (n ≥ m) by the start, end, middle or midpoint rule;
// `apcs` pads a single polyline by Algorithm 2. Longer inputs come back unchanged.
std::vector<Vec3> pad_points(std::span<const Vec3> points, std::size_t target_count, Padding padding);

// Frames G(t) = Gb + f(t)·(Ge − Gb) at t = i/T, i = 0 … T, for two point sequences of equal
// length. Frame 0 is `begin`, frame T is `end`, exactly. T is at least 1.
FrameSequence interpolate_frames(std::span<const Vec3> begin, std::span<const Vec3> end, int intervals, SpeedLaw law);

} // namespace apcs
