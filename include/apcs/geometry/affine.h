#pragma once

#include "apcs/geometry/vec3.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace apcs {

enum class Axis { x, y, z };

// A 3D affine map p ↦ M·p + t: the composition of a scene's moves, rotations and scales.
struct Affine {
    std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    Vec3 t;

    constexpr Vec3 operator()(const Vec3& p) const
    {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + t.x,
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + t.y,
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + t.z};
    }

    // (a ∘ b)(p) = a(b(p)): b first.
    friend constexpr Affine operator*(const Affine& a, const Affine& b)
    {
        Affine c;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 3; ++j)
                c.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        c.t = a(b.t);
        return c;
    }

    static constexpr Affine translation(const Vec3& by)
    {
        Affine a;
        a.t = by;
        return a;
    }

    // Uniform scale by `factor` about `centre`.
    static constexpr Affine scale_about(double factor, const Vec3& centre)
    {
        return scale_about(Vec3{factor, factor, factor}, centre);
    }

    // x, y and z each by its own factor, `centre` staying where it is.
    static constexpr Affine scale_about(const Vec3& factors, const Vec3& centre)
    {
        Affine a;
        a.m[0][0] = factors.x;
        a.m[1][1] = factors.y;
        a.m[2][2] = factors.z;
        a.t = centre - Vec3{centre.x * factors.x, centre.y * factors.y, centre.z * factors.z};
        return a;
    }

    // A turn of `degrees` by the right-hand rule about the line through `centre` along +axis.
    static Affine rotation_about(double degrees, Axis axis, const Vec3& centre)
    {
        const double radians = degrees * std::numbers::pi / 180.0;
        const double c = std::cos(radians);
        const double s = std::sin(radians);
        // The two coordinates the turn mixes: (u, v) ↦ (u·c − v·s, u·s + v·c).
        const std::size_t u = axis == Axis::x ? 1 : axis == Axis::y ? 2 : 0;
        const std::size_t v = axis == Axis::x ? 2 : axis == Axis::y ? 0 : 1;
        Affine a;
        a.m[u][u] = c;
        a.m[u][v] = -s;
        a.m[v][u] = s;
        a.m[v][v] = c;
        return translation(centre) * a * translation(-centre);
    }
};

} // namespace apcs
