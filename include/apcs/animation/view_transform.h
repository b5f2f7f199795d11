#pragma once

#include "apcs/geometry/bounding_box.h"
#include "apcs/geometry/pixel_point.h"
#include "apcs/geometry/vec3.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

namespace apcs {

// The viewer's direction in degrees (thesis Ch. 2.3): θ about the z axis, Φ from the z axis.
struct ViewAngles {
    double theta_degrees = 30.0;
    double phi_degrees = 40.0;
};

// Named views along the axes (SPEC §4.5: theta 0, phi 90 looks along -x).
struct ViewPreset {
    const char* name;
    ViewAngles angles;
    const char* shows; // the axes on the screen, right then up
};
inline constexpr ViewPreset view_presets[] = {
    {"front", {0.0, 90.0}, "+y right, +z up: the thesis' examples face-on"},
    {"side", {-90.0, 90.0}, "+x right, +z up"},
    {"top", {-90.0, 0.0}, "+x right, +y up: 2-D data of x y columns"},
};

// Eye coordinates: x_e right, y_e up, z_e depth (positive in front of the eye).
struct EyePoint {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

// A projected point in device pixels (Hercules: origin top-left, y down), not yet rounded.
struct DevicePoint {
    double x = 0.0;
    double y = 0.0;
    PixelPoint rounded() const;
};

// What a scene's points reach on the projection plane: the least and greatest x_e/z_e and y_e/z_e.
struct ProjectedExtent {
    double left = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    double top = 0.0;
    bool empty = true;

    void add(const EyePoint& eye);
    // Both extents' projections: as adding `other`'s points one by one after this one's (the
    // extremes of projections that are not NaN do not depend on their order; a tie keeps this one's).
    void join(const ProjectedExtent& other);
    // Whether `eye` lies inside, `margin` (a fraction of the extent's size) from every side.
    bool holds(const EyePoint& eye, double margin) const;
};

// World → eye → device (thesis VIEW_Transform, SPEC §4.5). The viewpoint sits at distance D from
// the scene centre; the device mapping is x_d = L + SCF·(d/S)·(x_e/z_e)·Vx,
// y_d = M − (d/S)·(y_e/z_e)·Vy with SCF = 1.5 and Vx = Vy = half the drawing area's height.
//
// Fitting rule (`fit`): D = 3·R, where R is half the diagonal of the scene's bounding box (1 if
// the scene is a single point), so every point is at least 2·R in front of the eye; d/S is then
// the largest value that keeps every projected point inside 90 % of the drawing area's half width
// and half height.
class ViewTransform {
public:
    static ViewTransform fit(ViewAngles angles, std::span<const Vec3> scene, PixelRect drawing_area);
    // The same for a scene too large to gather: for_each_point(visit) calls visit(point) for each
    // of its points, and is called twice.
    template <typename ForEachPoint>
    static ViewTransform fit_visiting(ViewAngles angles, ForEachPoint for_each_point, PixelRect drawing_area)
    {
        BoundingBox box;
        for_each_point([&](const Vec3& point) { box.add(point); });
        ViewTransform view = centred_on(angles, box, drawing_area);
        double widest = 0.0;
        double tallest = 0.0;
        for_each_point([&](const Vec3& point) {
            const EyePoint eye = view.to_eye(point);
            widest = std::max(widest, std::abs(eye.x / eye.z));
            tallest = std::max(tallest, std::abs(eye.y / eye.z));
        });
        view.focus_on(widest, tallest, drawing_area);
        return view;
    }

    EyePoint to_eye(const Vec3& world) const;
    DevicePoint to_device(const Vec3& world) const;
    // to_device(point).rounded() of the points (x[i], y[i], z[i]), i < x.size(), computed a column at
    // a time: the same operations in the same order, the same pixels.
    void to_pixels(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                   std::span<int> pixel_x, std::span<int> pixel_y) const;

    // Unit vectors in world coordinates along the screen's right and up, and toward the viewer:
    // a point moved along them moves right, up the screen, and nearer the eye (smaller z_e).
    Vec3 screen_right() const;
    Vec3 screen_up() const;
    Vec3 toward_viewer() const;

    double viewer_distance() const { return m_viewer_distance; }
    double focus() const { return m_focus; }
    Vec3 centre() const { return m_centre; }
    bool operator==(const ViewTransform&) const = default;

    // fit's two steps, for a scene that finds its extremes itself (world_drawing.h's ViewScene):
    // the view centred on the scene's box, then focused so that the largest |x_e/z_e| and |y_e/z_e|
    // of its points fill 90 % of the drawing area.
    static ViewTransform centred_on(ViewAngles angles, const BoundingBox& box, PixelRect drawing_area);
    void focus_on(double widest, double tallest, PixelRect drawing_area);

    // Filling (SPEC §7.2.1, the path screen): d/S the largest that keeps `extent` inside `area`
    // (all of it, at SCF), the extent's middle on the area's middle; a view centred_on a scene's box
    // before. A projection of almost no size (a straight path seen end on) is magnified no more
    // than 100 times the view that fits the scene's bounding sphere, so rounding dust is never
    // blown up to fill the screen.
    void fill(const ProjectedExtent& extent, PixelRect area);
    // The view magnified `factor` times (clamped to ≥ 1) with `about` (world) on the middle of
    // `area`; without `about`, what lies on the area's middle stays there.
    ViewTransform zoomed(double factor, std::optional<Vec3> about, PixelRect area) const;

private:
    ViewTransform(ViewAngles angles, Vec3 centre, double viewer_distance, PixelRect drawing_area);
    // L and M such that the projection (x_e/z_e, y_e/z_e) = (x, y) falls on the middle of `area`.
    void place(double x, double y, PixelRect area);
    EyePoint eye_of(double x, double y, double z) const;
    DevicePoint device_of(const EyePoint& eye) const;

    double m_sin_theta = 0.0;
    double m_cos_theta = 1.0;
    double m_sin_phi = 1.0;
    double m_cos_phi = 0.0;
    Vec3 m_centre;
    double m_viewer_distance = 1.0; // D
    double m_focus = 1.0;           // d/S
    double m_centre_x = 0.0;        // L
    double m_centre_y = 0.0;        // M
    double m_half_height = 1.0;     // Vx = Vy
};

} // namespace apcs
