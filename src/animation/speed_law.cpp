#include "apcs/animation/speed_law.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace apcs {

namespace {

constexpr std::array<std::pair<SpeedLaw, std::string_view>, 6> law_names{{
    {SpeedLaw::linear, "linear"},
    {SpeedLaw::ease_in, "ease-in"},
    {SpeedLaw::ease_out, "ease-out"},
    {SpeedLaw::ease_in_out, "ease-in-out"},
    {SpeedLaw::sqrt, "sqrt"},
    {SpeedLaw::square, "square"},
}};

} // namespace

double distance_fraction(SpeedLaw law, double time_fraction)
{
    const double t = std::clamp(time_fraction, 0.0, 1.0);
    using std::numbers::pi;
    switch (law) {
    case SpeedLaw::linear:
        return t;
    case SpeedLaw::ease_in:
        return 1.0 - std::cos(pi * t / 2.0);
    case SpeedLaw::ease_out:
        return std::sin(pi * t / 2.0);
    case SpeedLaw::ease_in_out:
        return (1.0 - std::cos(pi * t)) / 2.0;
    case SpeedLaw::sqrt:
        return std::sqrt(t);
    case SpeedLaw::square:
        return t * t;
    }
    return t;
}

std::optional<SpeedLaw> speed_law_from_name(std::string_view name)
{
    for (const auto& [law, law_name] : law_names)
        if (law_name == name)
            return law;
    return std::nullopt;
}

std::string_view speed_law_name(SpeedLaw law)
{
    for (const auto& [candidate, name] : law_names)
        if (candidate == law)
            return name;
    return "linear";
}

double acceleration_distance_fraction(double tau, double acceleration)
{
    const double a = std::clamp(acceleration, -1.0, 1.0);
    const double weight = std::abs(a);
    const SpeedLaw warp = a < 0 ? SpeedLaw::ease_out : SpeedLaw::ease_in;
    return (1.0 - weight) * std::clamp(tau, 0.0, 1.0) + weight * distance_fraction(warp, tau);
}

} // namespace apcs
