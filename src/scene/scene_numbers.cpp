#include "scene_numbers.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace apcs {

namespace {

// Units in the last place forgiven: a distance is a few operations (differences, a centroid, a
// square root) from its coordinates, each off by half a unit; 64 leaves room for a centroid of
// many points and for Kabsch's fit, and is still far below any tolerance a drawing is given.
constexpr double round_off_units = 64.0;

} // namespace

bool at_most_within_round_off(double value, double limit, double magnitude)
{
    const double scale = std::max({std::abs(value), std::abs(limit), std::abs(magnitude)});
    return value <= limit + round_off_units * std::numeric_limits<double>::epsilon() * scale;
}

} // namespace apcs
