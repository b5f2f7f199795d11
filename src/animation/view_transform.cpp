#include "apcs/animation/view_transform.h"

#include "apcs/geometry/hercules.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace apcs {

PixelPoint DevicePoint::rounded() const
{
    // Clamped far outside the raster so that the int conversion is always defined; rounded half
    // away from zero as std::lround does, but inline: lround is a library call, and drawing a
    // long path rounds millions of points (16 % of a keystroke on 10^5 control points).
    const auto to_int = [](double value) {
        const double clamped = std::clamp(value, -1e6, 1e6);
        return static_cast<int>(clamped < 0.0 ? clamped - 0.5 : clamped + 0.5);
    };
    return {to_int(x), to_int(y)};
}

ViewTransform::ViewTransform(ViewAngles angles, Vec3 centre, double viewer_distance, PixelRect drawing_area)
    : m_centre(centre)
    , m_viewer_distance(viewer_distance)
    , m_centre_x((drawing_area.left + drawing_area.right) / 2.0)
    , m_centre_y((drawing_area.top + drawing_area.bottom) / 2.0)
    , m_half_height(std::max(drawing_area.height() / 2.0, 1.0))
{
    const double theta = angles.theta_degrees * std::numbers::pi / 180.0;
    const double phi = angles.phi_degrees * std::numbers::pi / 180.0;
    m_sin_theta = std::sin(theta);
    m_cos_theta = std::cos(theta);
    m_sin_phi = std::sin(phi);
    m_cos_phi = std::cos(phi);
}

ViewTransform ViewTransform::fit(ViewAngles angles, std::span<const Vec3> scene, PixelRect drawing_area)
{
    return fit_visiting(
        angles,
        [&](const auto& visit) {
            for (const Vec3& point : scene)
                visit(point);
        },
        drawing_area);
}

ViewTransform ViewTransform::centred_on(ViewAngles angles, const BoundingBox& box, PixelRect drawing_area)
{
    const double radius = box.empty() || box.half_diagonal() <= 0.0 ? 1.0 : box.half_diagonal();
    return {angles, box.centre(), 3.0 * radius, drawing_area};
}

void ViewTransform::focus_on(double widest, double tallest, PixelRect drawing_area)
{
    const double half_width = std::max(drawing_area.width() / 2.0, 1.0);
    double focus = 0.0;
    if (widest > 0.0)
        focus = half_width / (hercules::aspect_correction * m_half_height * widest);
    if (tallest > 0.0)
        focus = focus > 0.0 ? std::min(focus, 1.0 / tallest) : 1.0 / tallest;
    m_focus = focus > 0.0 ? 0.9 * focus : 1.0;
}

EyePoint ViewTransform::to_eye(const Vec3& world) const
{
    const Vec3 p = world - m_centre;
    return {
        -p.x * m_sin_theta + p.y * m_cos_theta,
        -p.x * m_cos_theta * m_cos_phi - p.y * m_sin_theta * m_cos_phi + p.z * m_sin_phi,
        -p.x * m_cos_theta * m_sin_phi - p.y * m_sin_theta * m_sin_phi - p.z * m_cos_phi + m_viewer_distance,
    };
}

namespace {

// cos 90° is 6e-17 in doubles: a move along an axis must not leave such dust in a path file.
Vec3 without_dust(Vec3 direction)
{
    for (double* component : {&direction.x, &direction.y, &direction.z})
        if (std::abs(*component) < 1e-12)
            *component = 0.0;
    return direction;
}

} // namespace

// The rows of to_eye's rotation.
Vec3 ViewTransform::screen_right() const { return without_dust({-m_sin_theta, m_cos_theta, 0.0}); }
Vec3 ViewTransform::screen_up() const
{
    return without_dust({-m_cos_theta * m_cos_phi, -m_sin_theta * m_cos_phi, m_sin_phi});
}
Vec3 ViewTransform::toward_viewer() const
{
    return without_dust({m_cos_theta * m_sin_phi, m_sin_theta * m_sin_phi, m_cos_phi});
}

DevicePoint ViewTransform::to_device(const Vec3& world) const
{
    const EyePoint eye = to_eye(world);
    // Points at or behind the eye cannot occur for a fitted scene (z_e ≥ 2R); a tiny depth keeps
    // the mapping total for any other point.
    const double depth = std::max(eye.z, 1e-9);
    return {
        m_centre_x + hercules::aspect_correction * m_focus * (eye.x / depth) * m_half_height,
        m_centre_y - m_focus * (eye.y / depth) * m_half_height,
    };
}

} // namespace apcs
