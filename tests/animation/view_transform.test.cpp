#include "apcs/animation/view_transform.h"
#include "apcs/geometry/hercules.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace apcs;

namespace {
const PixelRect full_screen{0, 0, hercules::screen_width, hercules::screen_height};
}

TEST_CASE("theta 0, phi 90 looks along -x: +y is to the right and +z is up", "[animation][view]")
{
    const std::vector<Vec3> scene{{0, -1, -1}, {0, 1, 1}, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const ViewTransform view = ViewTransform::fit({0, 90}, scene, full_screen);
    const DevicePoint centre = view.to_device({0, 0, 0});
    const DevicePoint right = view.to_device({0, 1, 0});
    const DevicePoint up = view.to_device({0, 0, 1});
    REQUIRE(right.x > centre.x);
    REQUIRE(right.y == Approx(centre.y));
    REQUIRE(up.y < centre.y);
    REQUIRE(up.x == Approx(centre.x));
}

TEST_CASE("the scene centre lands on the centre of the drawing area (L, M)", "[animation][view]")
{
    const std::vector<Vec3> scene{{1, 2, 3}, {5, -2, 7}, {3, 4, -1}};
    const PixelRect area{20, 10, 700, 250};
    for (const ViewAngles angles : {ViewAngles{0, 90}, ViewAngles{30, 40}, ViewAngles{-75, 12}}) {
        const ViewTransform view = ViewTransform::fit(angles, scene, area);
        const DevicePoint centre = view.to_device({3, 1, 3});
        REQUIRE(centre.x == Approx(360.0));
        REQUIRE(centre.y == Approx(130.0));
    }
}

TEST_CASE("a square seen face-on is drawn 1.5 times wider than tall", "[animation][view]")
{
    const std::vector<Vec3> square{{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}};
    const ViewTransform view = ViewTransform::fit({0, 90}, square, full_screen);
    const DevicePoint low_left = view.to_device(square[0]);
    const DevicePoint high_right = view.to_device(square[2]);
    const double width = high_right.x - low_left.x;
    const double height = low_left.y - high_right.y;
    REQUIRE(width / height == Approx(hercules::aspect_correction));
}

TEST_CASE("the fitted view keeps every point inside the drawing area", "[animation][view]")
{
    const std::vector<Vec3> scene{{-50, 3, 0}, {80, 9, 40}, {10, -60, 5}, {0, 0, 100}};
    const PixelRect area{0, 0, 720, 280};
    for (const ViewAngles angles : {ViewAngles{0, 90}, ViewAngles{30, 40}, ViewAngles{200, -30}}) {
        const ViewTransform view = ViewTransform::fit(angles, scene, area);
        REQUIRE(view.viewer_distance() == Approx(3.0 * 0.5 * std::sqrt(130.0 * 130 + 69 * 69 + 100 * 100)));
        for (const Vec3& point : scene) {
            const PixelPoint pixel = view.to_device(point).rounded();
            REQUIRE(area.contains(pixel));
        }
    }
}

TEST_CASE("a scene of one point is drawn at the centre", "[animation][view]")
{
    const std::vector<Vec3> scene{{4, 4, 4}};
    const ViewTransform view = ViewTransform::fit({30, 40}, scene, full_screen);
    REQUIRE(view.to_device({4, 4, 4}).rounded() == PixelPoint{360, 174});
}

TEST_CASE("the screen's axes in the world: right, up the screen and toward the viewer", "[animation][view]")
{
    const std::vector<Vec3> scene{{-1, -1, -1}, {1, 1, 1}};
    for (const ViewAngles angles : {ViewAngles{30, 40}, ViewAngles{0, 90}, ViewAngles{-90, 0}, ViewAngles{200, 130}}) {
        const ViewTransform view = ViewTransform::fit(angles, scene, full_screen);
        const Vec3 point{0.2, -0.1, 0.3};
        const DevicePoint at = view.to_device(point);
        const EyePoint eye = view.to_eye(point);
        const DevicePoint right = view.to_device(point + 0.1 * view.screen_right());
        const DevicePoint up = view.to_device(point + 0.1 * view.screen_up());
        const EyePoint nearer = view.to_eye(point + 0.1 * view.toward_viewer());
        REQUIRE(right.x > at.x);
        REQUIRE(right.y == Approx(at.y));
        REQUIRE(up.y < at.y);
        // Along an eye axis only that eye coordinate changes, by the distance moved.
        const EyePoint eye_right = view.to_eye(point + 0.1 * view.screen_right());
        REQUIRE(eye_right.x - eye.x == Approx(0.1));
        REQUIRE(eye_right.y == Approx(eye.y));
        REQUIRE(eye_right.z == Approx(eye.z));
        REQUIRE(view.to_eye(point + 0.1 * view.screen_up()).y - eye.y == Approx(0.1));
        REQUIRE(eye.z - nearer.z == Approx(0.1));
        REQUIRE(nearer.x == Approx(eye.x));
        REQUIRE(nearer.y == Approx(eye.y));
    }
}

TEST_CASE("to_pixels gives each point's to_device(point).rounded(), near and far, behind the eye and halfway "
          "between pixels",
          "[animation][view]")
{
    const std::vector<Vec3> scene{{-3, -1, -2}, {3, 1, 2}};
    for (const ViewAngles angles : {ViewAngles{30, 40}, ViewAngles{0, 90}, ViewAngles{-90, 0}, ViewAngles{123, 17}}) {
        const ViewTransform view = ViewTransform::fit(angles, scene, full_screen);
        std::vector<double> x;
        std::vector<double> y;
        std::vector<double> z;
        const auto add = [&](const Vec3& point) {
            x.push_back(point.x);
            y.push_back(point.y);
            z.push_back(point.z);
        };
        for (int i = 0; i < 997; ++i) // an odd count: the loop's tail too
            add({std::sin(i * 0.37) * 5.0, std::cos(i * 0.11) * 4.0, std::sin(i * 1.7) * 3.0});
        // Far off the raster (clamped), at and behind the eye (the tiny depth), and not numbers.
        for (const double far : {1e9, -1e9, 1e300, -1e300})
            add({far, far / 3.0, -far});
        add(view.centre() + view.toward_viewer() * view.viewer_distance());
        add(view.centre() + view.toward_viewer() * (2.0 * view.viewer_distance()));
        // Points that project halfway between two pixels, either side of 0.
        for (const double device_x : {10.5, -10.5, 0.5, -0.5, 359.5}) {
            const DevicePoint at_centre = view.to_device(view.centre());
            const double world_per_pixel = 1.0 / (view.to_device(view.centre() + view.screen_right()).x - at_centre.x);
            add(view.centre() + view.screen_right() * ((device_x - at_centre.x) * world_per_pixel));
        }
        std::vector<int> pixel_x(x.size());
        std::vector<int> pixel_y(x.size());
        view.to_pixels(x, y, z, pixel_x, pixel_y);
        for (std::size_t i = 0; i < x.size(); ++i) {
            CAPTURE(i, x[i], y[i], z[i]);
            const PixelPoint one_by_one = view.to_device({x[i], y[i], z[i]}).rounded();
            REQUIRE(pixel_x[i] == one_by_one.x);
            REQUIRE(pixel_y[i] == one_by_one.y);
        }
    }
}

TEST_CASE("a point whose coordinates are not numbers rounds to a pixel far off the raster, defined", "[animation][view]")
{
    // Converting a NaN to int is undefined behaviour (UBSan's float-cast-overflow); on x86 it gave
    // INT_MIN. Clamped first, it lands where clipping drops it.
    const double not_a_number = std::nan("");
    REQUIRE(DevicePoint{not_a_number, not_a_number}.rounded() == PixelPoint{-1000000, -1000000});
    REQUIRE(DevicePoint{not_a_number, 3.4}.rounded() == PixelPoint{-1000000, 3});
    REQUIRE(DevicePoint{1e300, -1e300}.rounded() == PixelPoint{1000000, -1000000});
}
