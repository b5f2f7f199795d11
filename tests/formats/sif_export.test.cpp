#include "apcs/formats/sif_export.h"
#include "apcs/formats/sif_path.h"

#include "support/xml_elements.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace apcs;
using test::XmlElement;
using test::XmlReader;

namespace {

ViewAngles preset(std::string_view name)
{
    for (const ViewPreset& view : view_presets)
        if (name == view.name)
            return view.angles;
    FAIL("no preset " << name);
    return {};
}

// The document's elements; XmlReader knows no comments, so they are taken out first.
std::vector<XmlElement> elements_of(std::string document)
{
    for (std::size_t start = document.find("<!--"); start != std::string::npos; start = document.find("<!--"))
        document.erase(start, document.find("-->", start) + 3 - start);
    const auto elements = XmlReader::read(document);
    REQUIRE(elements);
    return *elements;
}

std::vector<XmlElement> named(const std::vector<XmlElement>& elements, std::string_view name)
{
    std::vector<XmlElement> found;
    std::ranges::copy_if(elements, std::back_inserter(found), [name](const XmlElement& e) { return e.name == name; });
    return found;
}

double number(const XmlElement& element) { return std::stod(element.text); }

const ControlPoints three_points{{{0, 0, 0}, {0.5, -0.25, 0.125, 0}},
                                 {{4, 2, 0}, {0, 0, 0, 0}},
                                 {{8, -2, 0}, {-0.5, 0.5, 0, 0}}};

} // namespace

TEST_CASE("The parallel view maps the named views' planes as SPEC 7.5 reads them back", "[sif]")
{
    const Vec3 point{1.5, -2.0, 3.0};
    const PlanePoint top = ParallelView(preset("top"))(point);
    CHECK(top.x == Approx(1.5).margin(1e-12));
    CHECK(top.y == Approx(-2.0).margin(1e-12));
    const PlanePoint front = ParallelView(preset("front"))(point);
    CHECK(front.x == Approx(-2.0).margin(1e-12));
    CHECK(front.y == Approx(3.0).margin(1e-12));
    const PlanePoint side = ParallelView(preset("side"))(point);
    CHECK(side.x == Approx(1.5).margin(1e-12));
    CHECK(side.y == Approx(3.0).margin(1e-12));
    // theta 30, phi 40 by SPEC 4.5: x_e = -x sin30 + y cos30, y_e = -x cos30 cos40 - y sin30 cos40 + z sin40.
    const PlanePoint session = ParallelView({30.0, 40.0})(point);
    CHECK(session.x == Approx(-1.5 * 0.5 - 2.0 * std::sqrt(3.0) / 2.0));
    CHECK(session.y == Approx(-1.5 * std::sqrt(3.0) / 2.0 * std::cos(40.0 * M_PI / 180.0) +
                              2.0 * 0.5 * std::cos(40.0 * M_PI / 180.0) + 3.0 * std::sin(40.0 * M_PI / 180.0)));
}

TEST_CASE("What TCB cannot carry: end slopes other than 1 1 and each non-zero acceleration", "[sif]")
{
    CHECK(sif_left_out(three_points, {1.0, 1.0}).empty());
    const auto slopes = sif_left_out(three_points, {0.5, 1.0});
    REQUIRE(slopes.size() == 1);
    CHECK(slopes[0].find("the end slopes 0.5 1") == 0);
    ControlPoints accelerated = three_points;
    accelerated[1].staff.acceleration = 0.3;
    const auto acceleration = sif_left_out(accelerated, {1.0, 1.0});
    REQUIRE(acceleration.size() == 1);
    CHECK(acceleration[0].find("the acceleration 0.3 of the span from control point 2 to 3") == 0);
}

TEST_CASE("A path's document: one TCB waypoint per control point, frames_per_span apart, its own t c b", "[sif]")
{
    const SifPathRequest request{three_points, {}, preset("top"), {10, 25.0}, SifMotion::tcb, {}, "a<b>.dat"};
    const std::string document = sif_path_document(request);
    const std::vector<XmlElement> elements = elements_of(document);
    const XmlElement& canvas = elements.front();
    CHECK(canvas.name == "canvas");
    CHECK(canvas.attributes.at("fps") == "25");
    CHECK(canvas.attributes.at("end-time") == "20f");
    CHECK(named(elements, "name").front().text == "a<b>.dat");

    const std::vector<XmlElement> waypoints = named(elements, "waypoint");
    REQUIRE(waypoints.size() == 3);
    CHECK(waypoints[0].attributes.at("time") == "0f");
    CHECK(waypoints[1].attributes.at("time") == "10f");
    CHECK(waypoints[2].attributes.at("time") == "20f");
    for (const XmlElement& waypoint : waypoints) {
        CHECK(waypoint.attributes.at("before") == "auto");
        CHECK(waypoint.attributes.at("after") == "auto");
    }
    CHECK(waypoints[0].attributes.at("tension") == "0.5");
    CHECK(waypoints[0].attributes.at("continuity") == "-0.25");
    CHECK(waypoints[0].attributes.at("bias") == "0.125");
    CHECK(waypoints[2].attributes.at("tension") == "-0.5");
    CHECK(waypoints[2].attributes.at("continuity") == "0.5");

    // The view box holds every control point; its units per pixel are the same both ways.
    double left = 0, top = 0, right = 0, bottom = 0;
    std::sscanf(canvas.attributes.at("view-box").c_str(), "%lf %lf %lf %lf", &left, &top, &right, &bottom);
    for (const ControlPoint& point : three_points) {
        CHECK((left < point.position.x && point.position.x < right));
        CHECK((bottom < point.position.y && point.position.y < top));
    }
    const double width = std::stod(canvas.attributes.at("width"));
    const double height = std::stod(canvas.attributes.at("height"));
    CHECK((right - left) / width == Approx((top - bottom) / height));
    CHECK(std::max(width, height) == 480);
}

TEST_CASE("The path's outline carries the KB tangents as Hermite tangents, the marks every control point", "[sif]")
{
    const SifPathRequest request{three_points, {}, preset("top"), {}, SifMotion::tcb, {}, "three.dat"};
    const std::vector<XmlElement> elements = elements_of(sif_path_document(request));
    const std::vector<XmlElement> xs = named(elements, "x");
    const std::vector<XmlElement> ys = named(elements, "y");
    // The first vertex: the point (0, 0), t1 = t2 = P1 − P0 = (4, 2) (slope 1). The middle one:
    // DS = DD = (P2 − P0)/2 = (4, −1) at t = c = b = 0.
    REQUIRE(xs.size() >= 9);
    CHECK(number(xs[0]) == 0.0);
    CHECK(number(xs[1]) == Approx(4.0));
    CHECK(number(ys[1]) == Approx(2.0));
    CHECK(number(xs[2]) == Approx(4.0));
    CHECK(number(xs[3]) == Approx(4.0));
    CHECK(number(ys[3]) == Approx(2.0));
    CHECK(number(xs[4]) == Approx(4.0));
    CHECK(number(ys[4]) == Approx(-1.0));
    CHECK(number(xs[5]) == Approx(4.0));
    CHECK(number(ys[5]) == Approx(-1.0));
    const auto layers = named(elements, "layer");
    const auto marks = std::ranges::count_if(layers, [](const XmlElement& layer) {
        return layer.attributes.at("desc").starts_with("control point ");
    });
    CHECK(marks == 3);
    CHECK(layers.back().attributes.at("desc") == "the point");
}

TEST_CASE("--sif-motion frames: one linear waypoint a frame, at APCS's positions", "[sif]")
{
    const std::vector<Vec3> frames{{0, 0, 0}, {1, 0.5, 0}, {2.5, 1, 0}, {8, -2, 0}};
    const SifPathRequest request{three_points, {0.0, 0.0}, preset("top"), {}, SifMotion::frames, frames, "f.dat"};
    const std::string document = sif_path_document(request);
    const std::vector<XmlElement> elements = elements_of(document);
    const std::vector<XmlElement> waypoints = named(elements, "waypoint");
    REQUIRE(waypoints.size() == 4);
    for (std::size_t f = 0; f < waypoints.size(); ++f) {
        CHECK(waypoints[f].attributes.at("time") == std::to_string(f) + "f");
        CHECK(waypoints[f].attributes.at("before") == "linear");
    }
    CHECK(elements.front().attributes.at("end-time") == "3f");
    // Slopes 0 0 are kept by the frames: nothing is said to be left out.
    CHECK(document.find("Not carried") == std::string::npos);
}

TEST_CASE("An animation's document: an outline per part, each vertex through every frame", "[sif]")
{
    Graphic structure;
    structure.parts.push_back({"stroke", Closure::open, {{0, 0, 0}, {1, 0, 0}}});
    structure.parts.push_back({"", Closure::closed, {{0, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 1, 0}}});
    // Frame 0 closes the second part by its first and last points meeting; later frames move its
    // last point away: the outline is looped in every frame, its 4 vertices throughout.
    FrameSequence frames(3, 6);
    for (std::size_t f = 0; f < 3; ++f)
        for (std::size_t p = 0; p < 6; ++p)
            frames.frame(f)[p] = structure.all_points()[p] + Vec3{static_cast<double>(f), p == 5 ? 0.5 * static_cast<double>(f) : 0.0, 0};
    const SifAnimationRequest request{structure, frames, preset("top"), 24.0, "a to b"};
    const std::string document = sif_animation_document(request);
    const std::vector<XmlElement> elements = elements_of(document);
    const auto layers = named(elements, "layer");
    REQUIRE(layers.size() == 2);
    CHECK(layers[0].attributes.at("desc") == "stroke");
    CHECK(layers[1].attributes.at("desc") == "part 2");
    const auto blines = named(elements, "bline");
    REQUIRE(blines.size() == 2);
    CHECK(blines[0].attributes.at("loop") == "false");
    CHECK(blines[1].attributes.at("loop") == "true");
    // 2 + 4 vertices, 3 frames each.
    CHECK(named(elements, "waypoint").size() == 18);
    CHECK(elements.front().attributes.at("end-time") == "2f");
    // The last vertex in the last frame is the frame's own point (2, 2), not a point of another.
    CHECK(document.find("<waypoint time=\"2f\" before=\"linear\" after=\"linear\"><vector><x>2.000000000</x><y>2."
                        "000000000</y></vector></waypoint>\n      </animated></point>") != std::string::npos);
}

TEST_CASE("A document that names what it leaves out, or a name that is not UTF-8, is still XML", "[sif]")
{
    ControlPoints accelerated = three_points;
    accelerated[0].staff.acceleration = 0.6;
    const std::string document = sif_path_document(
        {accelerated, {0.5, 1.0}, preset("top"), {}, SifMotion::tcb, {}, std::string("caf\xe9 -- <b>.dat")});
    CHECK(document.find("Not carried") != std::string::npos);
    const Expected<SifPath> read = parse_sif_path(document, "left-out.sif", {});
    INFO((read ? std::string() : read.error().to_string()));
    REQUIRE(read);
    CHECK(read->file.parts.at(0).points.size() == 3);
    CHECK(document.find("<name>caf\xef\xbf\xbd -- &lt;b&gt;.dat</name>") != std::string::npos);
}

TEST_CASE("A path's document read back is the path: positions to 1e-9, the staff values exactly", "[sif]")
{
    for (const char* view : {"top", "front", "side"}) {
        INFO(view);
        // Points in the view's plane: (u, v) of the top view laid into the named view's plane.
        ControlPoints points = three_points;
        const SifPlane plane = sif_plane_of(preset(view).theta_degrees, preset(view).phi_degrees);
        for (ControlPoint& point : points) {
            const Vec3 flat = point.position;
            if (plane == SifPlane::front)
                point.position = {0.0, flat.x, flat.y};
            else if (plane == SifPlane::side)
                point.position = {flat.x, 0.0, flat.y};
        }
        const std::string document =
            sif_path_document({points, {}, preset(view), {}, SifMotion::tcb, {}, "three.dat"});
        const Expected<SifPath> read = parse_sif_path(document, "three.sif", {"origin", plane});
        REQUIRE(read);
        CHECK(read->warnings.empty());
        const std::vector<DatPoint>& back = read->file.parts.at(0).points;
        REQUIRE(back.size() == points.size());
        for (std::size_t k = 0; k < points.size(); ++k) {
            CHECK(back[k].position.x == Approx(points[k].position.x).margin(1e-9));
            CHECK(back[k].position.y == Approx(points[k].position.y).margin(1e-9));
            CHECK(back[k].position.z == Approx(points[k].position.z).margin(1e-9));
            REQUIRE(back[k].staff);
            CHECK(*back[k].staff == points[k].staff);
        }
    }
}

TEST_CASE("Waypoints are written exactly: a path far from the origin reads back to the bit", "[sif]")
{
    const ControlPoints far{{{999999999.0, 0.0, 0.0}, {}}, {{999999999.25, 0.04, 0.0}, {}}, {{999999999.5, -0.03, 0.0}, {}}};
    const Expected<SifPath> read =
        parse_sif_path(sif_path_document({far, {}, preset("top"), {}, SifMotion::tcb, {}, "far.dat"}), "far.sif", {});
    REQUIRE(read);
    const std::vector<DatPoint>& back = read->file.parts.at(0).points;
    REQUIRE(back.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
        CHECK(back[k].position.x == far[k].position.x);
        CHECK(back[k].position.y == far[k].position.y);
    }
}
