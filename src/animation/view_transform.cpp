#include "apcs/animation/view_transform.h"

#include "apcs/geometry/hercules.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace apcs {

namespace {

// Clamped far outside the raster so that the int conversion is always defined; rounded half away
// from zero as std::lround does, but inline: lround is a library call, and drawing a long path
// rounds millions of points (16 % of a keystroke on 10^5 control points). The bound comes first in
// each comparison: std::max(bound, NaN) is the bound (NaN compares false), so a NaN lands off the
// raster instead of reaching the conversion, whose result for NaN is undefined.
int rounded_half_away(double value)
{
    const double clamped = std::min(1e6, std::max(-1e6, value));
    // Both computed, one chosen: no branch, so that a loop of them is done several at once.
    const double down = clamped - 0.5;
    const double up = clamped + 0.5;
    return static_cast<int>(clamped < 0.0 ? down : up);
}

} // namespace

PixelPoint DevicePoint::rounded() const { return {rounded_half_away(x), rounded_half_away(y)}; }

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

void ProjectedExtent::add(const EyePoint& eye)
{
    const double x = eye.x / eye.z;
    const double y = eye.y / eye.z;
    if (empty) {
        *this = {x, x, y, y, false};
        return;
    }
    left = std::min(left, x);
    right = std::max(right, x);
    bottom = std::min(bottom, y);
    top = std::max(top, y);
}

void ProjectedExtent::join(const ProjectedExtent& other)
{
    if (other.empty)
        return;
    if (empty) {
        *this = other;
        return;
    }
    left = std::min(left, other.left);
    right = std::max(right, other.right);
    bottom = std::min(bottom, other.bottom);
    top = std::max(top, other.top);
}

bool ProjectedExtent::holds(const EyePoint& eye, double margin) const
{
    if (empty || !(eye.z > 0.0))
        return false;
    const double x = eye.x / eye.z;
    const double y = eye.y / eye.z;
    const double x_margin = margin * (right - left);
    const double y_margin = margin * (top - bottom);
    return x > left + x_margin && x < right - x_margin && y > bottom + y_margin && y < top - y_margin;
}

void ViewTransform::fill(const ProjectedExtent& extent, PixelRect area)
{
    // The bounding sphere (radius R, seen from 3R) reaches about 1/3 either side of the middle.
    constexpr double largest_focus = 100.0 * 3.0;
    const double width = hercules::aspect_correction * m_half_height * (extent.right - extent.left);
    const double height = m_half_height * (extent.top - extent.bottom);
    double focus = largest_focus;
    if (width > 0.0)
        focus = std::min(focus, std::max(area.width(), 1) / width);
    if (height > 0.0)
        focus = std::min(focus, std::max(area.height(), 1) / height);
    m_focus = focus;
    if (!extent.empty)
        place((extent.left + extent.right) / 2.0, (extent.bottom + extent.top) / 2.0, area);
}

ViewTransform ViewTransform::zoomed(double factor, std::optional<Vec3> about, PixelRect area) const
{
    // The projection (x_e/z_e, y_e/z_e) to bring to the middle: to_device's mapping inverted there.
    double x = ((area.left + area.right) / 2.0 - m_centre_x) / (hercules::aspect_correction * m_focus * m_half_height);
    double y = (m_centre_y - (area.top + area.bottom) / 2.0) / (m_focus * m_half_height);
    if (about) {
        const EyePoint eye = to_eye(*about);
        const double depth = std::max(eye.z, 1e-9);
        x = eye.x / depth;
        y = eye.y / depth;
    }
    ViewTransform view = *this;
    view.m_focus = m_focus * std::max(factor, 1.0);
    view.place(x, y, area);
    return view;
}

void ViewTransform::place(double x, double y, PixelRect area)
{
    m_centre_x = (area.left + area.right) / 2.0 - hercules::aspect_correction * m_focus * x * m_half_height;
    m_centre_y = (area.top + area.bottom) / 2.0 + m_focus * y * m_half_height;
}

inline EyePoint ViewTransform::eye_of(double x, double y, double z) const
{
    const double px = x - m_centre.x;
    const double py = y - m_centre.y;
    const double pz = z - m_centre.z;
    return {
        -px * m_sin_theta + py * m_cos_theta,
        -px * m_cos_theta * m_cos_phi - py * m_sin_theta * m_cos_phi + pz * m_sin_phi,
        -px * m_cos_theta * m_sin_phi - py * m_sin_theta * m_sin_phi - pz * m_cos_phi + m_viewer_distance,
    };
}

inline DevicePoint ViewTransform::device_of(const EyePoint& eye) const
{
    // Points at or behind the eye cannot occur for a fitted scene (z_e ≥ 2R); a tiny depth keeps
    // the mapping total for any other point.
    const double depth = std::max(eye.z, 1e-9);
    return {
        m_centre_x + hercules::aspect_correction * m_focus * (eye.x / depth) * m_half_height,
        m_centre_y - m_focus * (eye.y / depth) * m_half_height,
    };
}

EyePoint ViewTransform::to_eye(const Vec3& world) const { return eye_of(world.x, world.y, world.z); }

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

DevicePoint ViewTransform::to_device(const Vec3& world) const { return device_of(to_eye(world)); }

// One point after another as to_device and rounded do, in a loop of no branch but selections: the
// compiler does two or four points in one instruction, divisions included.
void ViewTransform::to_pixels(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                              std::span<int> pixel_x, std::span<int> pixel_y) const
{
    for (std::size_t i = 0; i < x.size(); ++i) {
        const DevicePoint device = device_of(eye_of(x[i], y[i], z[i]));
        pixel_x[i] = rounded_half_away(device.x);
        pixel_y[i] = rounded_half_away(device.y);
    }
}

} // namespace apcs
