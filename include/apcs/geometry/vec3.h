#pragma once

#include <algorithm>
#include <cmath>

namespace apcs {

// A point or vector in world units (the units of the .dat files).
struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    constexpr Vec3& operator+=(const Vec3& other)
    {
        x += other.x;
        y += other.y;
        z += other.z;
        return *this;
    }
    constexpr Vec3& operator-=(const Vec3& other)
    {
        x -= other.x;
        y -= other.y;
        z -= other.z;
        return *this;
    }
    constexpr Vec3& operator*=(double factor)
    {
        x *= factor;
        y *= factor;
        z *= factor;
        return *this;
    }
    friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

constexpr Vec3 operator+(Vec3 left, const Vec3& right) { return left += right; }
constexpr Vec3 operator-(Vec3 left, const Vec3& right) { return left -= right; }
constexpr Vec3 operator*(Vec3 vector, double factor) { return vector *= factor; }
constexpr Vec3 operator*(double factor, Vec3 vector) { return vector *= factor; }
constexpr Vec3 operator-(const Vec3& vector) { return {-vector.x, -vector.y, -vector.z}; }

constexpr double dot(const Vec3& left, const Vec3& right)
{
    return left.x * right.x + left.y * right.y + left.z * right.z;
}

inline double length(const Vec3& vector) { return std::sqrt(dot(vector, vector)); }
inline double distance(const Vec3& from, const Vec3& to) { return length(to - from); }

// The largest |coordinate| of `point`: the scale of the round-off in what is computed from it.
inline double largest_coordinate(const Vec3& point)
{
    return std::max({std::abs(point.x), std::abs(point.y), std::abs(point.z)});
}

// Linear interpolation: `from` at fraction 0, `to` at fraction 1.
constexpr Vec3 lerp(const Vec3& from, const Vec3& to, double fraction)
{
    return from + (to - from) * fraction;
}

} // namespace apcs
