#include "apcs/formats/sif_export.h"

#include "apcs/animation/kochanek_bartels.h"
#include "apcs/animation/motion_path.h"
#include "apcs/base/utf8.h"
#include "apcs/formats/number_text.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>
#include <cmath>
#include <numbers>

namespace apcs {

namespace {

// sin and cos of an angle in degrees, exactly 0 and ±1 at multiples of 90 degrees: the named views
// then give (x, y) as they are, not 4 + 2·6e-17, in the document and on the way back.
std::pair<double, double> sine_and_cosine(double degrees)
{
    const double quarters = degrees / 90.0;
    if (quarters == std::round(quarters) && std::abs(quarters) < 1e9) {
        constexpr std::array<std::pair<double, double>, 4> exact{{{0.0, 1.0}, {1.0, 0.0}, {0.0, -1.0}, {-1.0, 0.0}}};
        const auto quarter = static_cast<long long>(quarters);
        return exact[static_cast<std::size_t>(((quarter % 4) + 4) % 4)];
    }
    constexpr double radians_per_degree = std::numbers::pi / 180.0;
    return {std::sin(degrees * radians_per_degree), std::cos(degrees * radians_per_degree)};
}

} // namespace

ParallelView::ParallelView(ViewAngles angles)
{
    std::tie(m_sin_theta, m_cos_theta) = sine_and_cosine(angles.theta_degrees);
    std::tie(m_sin_phi, m_cos_phi) = sine_and_cosine(angles.phi_degrees);
}

PlanePoint ParallelView::operator()(const Vec3& world) const
{
    return {-world.x * m_sin_theta + world.y * m_cos_theta,
            -world.x * m_cos_theta * m_cos_phi - world.y * m_sin_theta * m_cos_phi + world.z * m_sin_phi};
}

std::vector<std::string> sif_left_out(std::span<const ControlPoint> points, EndSlopes slopes)
{
    std::vector<std::string> left_out;
    if (slopes.start != 1.0 || slopes.end != 1.0)
        left_out.push_back("the end slopes " + shortest_number(slopes.start) + " " + shortest_number(slopes.end) +
                           ": Synfig's TCB leaves the first waypoint along P1 - P0 and reaches the last along "
                           "Pn - Pn-1 (slopes 1 1)");
    for (const AccelerationSpan& span : acceleration_spans(points))
        if (span.acceleration != 0.0 && span.first_point != span.last_point)
            left_out.push_back("the acceleration " + shortest_number(span.acceleration) + " of the span from control point " +
                               std::to_string(span.first_point + 1) + " to " + std::to_string(span.last_point + 1) +
                               ": Synfig moves between waypoints at the spline's own pace");
    return left_out;
}

namespace {

// The part of the view plane a document shows: its points' extent, a tenth more on every side.
struct PlaneBox {
    double left = 0.0;
    double right = 0.0;
    double bottom = 0.0;
    double top = 0.0;
    bool empty = true;

    void add(PlanePoint point)
    {
        if (empty) {
            left = right = point.x;
            bottom = top = point.y;
            empty = false;
            return;
        }
        left = std::min(left, point.x);
        right = std::max(right, point.x);
        bottom = std::min(bottom, point.y);
        top = std::max(top, point.y);
    }
    // The larger side; 1 for a box of no size, so that a path of one point still has a canvas.
    double size() const
    {
        const double larger = std::max(right - left, top - bottom);
        return larger > 0.0 ? larger : 1.0;
    }
};

constexpr int longer_side_pixels = 480;
constexpr int shorter_side_least_pixels = 120;

void append_number(std::string& text, double value) { append_shortest(text, value); }

// XML 1.0's characters (its production Char): others cannot stand in a document, even escaped.
bool is_xml_character(char32_t c)
{
    return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
           (c >= 0x10000 && c <= 0x10FFFF);
}

// `raw` (a file or part name, a sentence) as the text of an element or an attribute: the markup
// characters escaped, bytes that are not UTF-8 read as U+FFFD, what XML cannot hold as '?'.
void append_escaped(std::string& text, std::string_view raw)
{
    for (const char32_t c : decode_utf8(raw)) {
        switch (c) {
        case U'&': text += "&amp;"; break;
        case U'<': text += "&lt;"; break;
        case U'>': text += "&gt;"; break;
        case U'"': text += "&quot;"; break;
        default:
            if (is_xml_character(c) && c >= 0x20)
                append_utf8(text, c);
            else
                text += c == U'\t' ? '\t' : '?';
        }
    }
}

// `raw` inside a comment, which XML ends at the first "--": each "--" is written "- -".
void append_comment_text(std::string& text, std::string_view raw)
{
    std::string escaped;
    append_escaped(escaped, raw);
    for (const char c : escaped) {
        if (c == '-' && !text.empty() && text.back() == '-')
            text += ' ';
        text += c;
    }
}

// The view plane's points as a document writes them, projected. What is drawn (the outline, the
// marks, an animation's parts) with the decimals that keep 0.5e-9 of the drawing's size
// (decimals_for_size: shorter and faster to write and read than the shortest exact form); the
// path's own waypoints exactly, so that a document read back gives the very numbers projected.
class PlaneText {
public:
    PlaneText(const ParallelView& view, double drawing_size) : m_view(view), m_decimals(decimals_for_size(drawing_size))
    {
    }
    PlanePoint at(const Vec3& world) const { return m_view(world); }
    void vector(std::string& text, PlanePoint point) const
    {
        text += "<vector><x>";
        append_fixed(text, point.x, m_decimals);
        text += "</x><y>";
        append_fixed(text, point.y, m_decimals);
        text += "</y></vector>";
    }
    static void exact_vector(std::string& text, PlanePoint point)
    {
        text += "<vector><x>";
        append_shortest(text, point.x);
        text += "</x><y>";
        append_shortest(text, point.y);
        text += "</y></vector>";
    }

private:
    ParallelView m_view;
    int m_decimals;
};

void append_frame_time(std::string& text, long long frame)
{
    text += std::to_string(frame);
    text += 'f';
}

void append_real_param(std::string& text, std::string_view name, double value)
{
    text += "    <param name=\"";
    text += name;
    text += "\"><real value=\"";
    append_number(text, value);
    text += "\"/></param>\n";
}

void append_colour_param(std::string& text, double red, double green, double blue)
{
    text += "    <param name=\"color\"><color><r>";
    append_number(text, red);
    text += "</r><g>";
    append_number(text, green);
    text += "</g><b>";
    append_number(text, blue);
    text += "</b><a>1</a></color></param>\n";
}

// The canvas element's opening: the box and its margin, the longer side 480 pixels.
void append_canvas_start(std::string& text, const PlaneBox& shown, double fps, long long end_frame,
                         std::string_view name)
{
    const double margin = shown.size() / 10.0;
    const double width = (shown.right - shown.left) + 2.0 * margin;
    const double height = (shown.top - shown.bottom) + 2.0 * margin;
    const double units_per_pixel = std::max(width, height) / longer_side_pixels;
    // A thin path's canvas is widened around it, never stretched: a unit is as many pixels both ways.
    const auto pixels = [units_per_pixel](double extent) {
        return std::max(shorter_side_least_pixels, static_cast<int>(std::lround(extent / units_per_pixel)));
    };
    const int width_pixels = pixels(width);
    const int height_pixels = pixels(height);
    const double middle_x = (shown.left + shown.right) / 2.0;
    const double middle_y = (shown.bottom + shown.top) / 2.0;
    text += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<canvas version=\"1.2\" width=\"" +
            std::to_string(width_pixels) + "\" height=\"" + std::to_string(height_pixels) +
            "\" xres=\"2834.645669\" yres=\"2834.645669\" gamma-r=\"1\" gamma-g=\"1\" gamma-b=\"1\" view-box=\"";
    append_number(text, middle_x - units_per_pixel * width_pixels / 2.0);
    text += ' ';
    append_number(text, middle_y + units_per_pixel * height_pixels / 2.0);
    text += ' ';
    append_number(text, middle_x + units_per_pixel * width_pixels / 2.0);
    text += ' ';
    append_number(text, middle_y - units_per_pixel * height_pixels / 2.0);
    text += "\" antialias=\"1\" fps=\"";
    append_number(text, fps);
    text += "\" begin-time=\"0f\" end-time=\"";
    append_frame_time(text, end_frame);
    text += "\" bgcolor=\"1 1 1 1\">\n  <name>";
    append_escaped(text, name);
    text += "</name>\n";
}

void append_layer_start(std::string& text, std::string_view type, std::string_view description)
{
    text += "  <layer type=\"";
    text += type;
    text += "\" active=\"true\" exclude_from_rendering=\"false\" version=\"0.2\" desc=\"";
    append_escaped(text, description);
    text += "\">\n";
    append_real_param(text, "z_depth", 0.0);
    append_real_param(text, "amount", 1.0);
    text += "    <param name=\"blend_method\"><integer value=\"0\"/></param>\n";
}

// A vertex of an outline: its point (a vector or an animated one, already written), and its
// tangents in (t1, arriving) and out (t2, leaving), which Synfig takes as Hermite tangents.
void append_bline_vertex(std::string& text, const PlaneText& plane, std::string_view point, PlanePoint arriving,
                         PlanePoint leaving)
{
    text += "      <entry><composite type=\"bline_point\"><point>";
    text += point;
    text += "</point><width><real value=\"1\"/></width><origin><real value=\"0.5\"/></origin>"
            "<split><bool value=\"true\"/></split><t1>";
    plane.vector(text, arriving);
    text += "</t1><t2>";
    plane.vector(text, leaving);
    text += "</t2><split_radius><bool value=\"true\"/></split_radius>"
            "<split_angle><bool value=\"true\"/></split_angle></composite></entry>\n";
}

void append_outline_end(std::string& text, double width, double grey)
{
    text += "    </bline></param>\n";
    append_real_param(text, "width", width);
    append_real_param(text, "expand", 0.0);
    append_colour_param(text, grey, grey, grey);
    text += "    <param name=\"origin\"><vector><x>0</x><y>0</y></vector></param>\n"
            "    <param name=\"invert\"><bool value=\"false\"/></param>\n"
            "    <param name=\"antialias\"><bool value=\"true\"/></param>\n"
            "    <param name=\"feather\"><real value=\"0\"/></param>\n"
            "    <param name=\"sharp_cusps\"><bool value=\"true\"/></param>\n"
            "    <param name=\"round_tip[0]\"><bool value=\"true\"/></param>\n"
            "    <param name=\"round_tip[1]\"><bool value=\"true\"/></param>\n"
            "    <param name=\"homogeneous\"><bool value=\"false\"/></param>\n"
            "  </layer>\n";
}

void append_outline_start(std::string& text, std::string_view description, bool loop)
{
    append_layer_start(text, "outline", description);
    text += "    <param name=\"bline\"><bline type=\"bline_point\" loop=\"";
    text += loop ? "true" : "false";
    text += "\">\n";
}

PlanePoint projected_tangent(const PlaneText& plane, const Vec3& tangent)
{
    // The projection is linear (no translation), so a tangent projects as a point does.
    return plane.at(tangent);
}

// The path's curve, exactly: one vertex per control point, the KB tangents as its Hermite tangents.
void append_path_outline(std::string& text, const SifPathRequest& request, std::span<const HermiteSegment> segments,
                         const PlaneText& plane, double width)
{
    append_outline_start(text, "the path", false);
    for (std::size_t k = 0; k < request.points.size(); ++k) {
        const PointTangents tangents = tangents_at(segments, k);
        std::string point;
        plane.vector(point, plane.at(request.points[k].position));
        const PlanePoint arriving = tangents.incoming ? projected_tangent(plane, *tangents.incoming) : PlanePoint{};
        const PlanePoint leaving = tangents.outgoing ? projected_tangent(plane, *tangents.outgoing) : arriving;
        append_bline_vertex(text, plane, point, tangents.incoming ? arriving : leaving, leaving);
    }
    append_outline_end(text, width, 0.6);
}

void append_circle(std::string& text, std::string_view description, double radius, std::string_view origin,
                   double red, double grey)
{
    append_layer_start(text, "circle", description);
    append_colour_param(text, red, grey, grey);
    append_real_param(text, "radius", radius);
    append_real_param(text, "feather", 0.0);
    text += "    <param name=\"origin\">";
    text += origin;
    text += "</param>\n    <param name=\"invert\"><bool value=\"false\"/></param>\n  </layer>\n";
}

void append_control_point_marks(std::string& text, const SifPathRequest& request, const PlaneText& plane,
                                double radius)
{
    if (request.points.size() > most_marked_control_points) {
        text += "  <!-- The control points are not marked: there are more than " +
                std::to_string(most_marked_control_points) + " of them. -->\n";
        return;
    }
    for (std::size_t k = 0; k < request.points.size(); ++k) {
        std::string origin;
        plane.vector(origin, plane.at(request.points[k].position));
        append_circle(text, "control point " + std::to_string(k + 1), radius, origin, 0.25, 0.25);
    }
}

void append_tcb_waypoint(std::string& text, long long frame, const ControlPoint& point, const PlaneText& plane)
{
    text += "      <waypoint time=\"";
    append_frame_time(text, frame);
    text += "\" before=\"auto\" after=\"auto\" tension=\"";
    append_number(text, point.staff.tension);
    text += "\" continuity=\"";
    append_number(text, point.staff.continuity);
    text += "\" bias=\"";
    append_number(text, point.staff.bias);
    text += "\" temporal-tension=\"0\">";
    PlaneText::exact_vector(text, plane.at(point.position));
    text += "</waypoint>\n";
}

// A path's frames are written exactly (they are what a document read back gives); a drawing's
// vertices with the drawing's decimals.
enum class Precision { drawn, exact };

void append_linear_waypoint(std::string& text, const PlaneText& plane, long long frame, PlanePoint position,
                            Precision precision, std::string_view indent)
{
    text += indent;
    text += "<waypoint time=\"";
    append_frame_time(text, frame);
    text += "\" before=\"linear\" after=\"linear\">";
    if (precision == Precision::exact)
        PlaneText::exact_vector(text, position);
    else
        plane.vector(text, position);
    text += "</waypoint>\n";
}

std::string moving_origin(const SifPathRequest& request, const PlaneText& plane)
{
    std::string origin;
    // A waypoint is under 260 bytes: a path of 10^5 points is not copied as its text grows.
    origin.reserve((request.points.size() + request.frames.size()) * 260 + 64);
    origin += "\n      <animated type=\"vector\">\n";
    if (request.motion == SifMotion::tcb) {
        for (std::size_t k = 0; k < request.points.size(); ++k)
            append_tcb_waypoint(origin, static_cast<long long>(k) * request.timing.frames_per_span, request.points[k],
                                plane);
    } else {
        for (std::size_t f = 0; f < request.frames.size(); ++f)
            append_linear_waypoint(origin, plane, static_cast<long long>(f), plane.at(request.frames[f]),
                                   Precision::exact, "      ");
    }
    origin += "      </animated>\n    ";
    return origin;
}

void append_left_out_comment(std::string& text, const SifPathRequest& request)
{
    if (request.motion == SifMotion::frames) {
        text += "  <!-- The circle moves through APCS's own frames (KEY1, the in-betweens, KEY2), one linear "
                "waypoint a frame: acceleration and end slopes are kept; between frames it moves along chords. -->\n";
        return;
    }
    const std::vector<std::string> left_out = sif_left_out(request.points, request.slopes);
    if (left_out.empty())
        return;
    text += "  <!-- Not carried by Synfig's TCB waypoints (an export with sif-motion frames keeps them):\n";
    for (const std::string& sentence : left_out) {
        text += "       ";
        append_comment_text(text, sentence);
        text += ".\n";
    }
    text += "  -->\n";
}

long long last_frame_of(const SifPathRequest& request)
{
    if (request.motion == SifMotion::frames)
        return request.frames.empty() ? 0 : static_cast<long long>(request.frames.size()) - 1;
    return static_cast<long long>(request.points.size() - 1) * request.timing.frames_per_span;
}

PlaneBox path_box(const SifPathRequest& request, std::span<const HermiteSegment> segments, const ParallelView& view)
{
    PlaneBox box;
    // A segment lies inside the hull of its Bézier points P0, P0 + T0/3, P1 − T1/3, P1: their box
    // holds the curve (a little more where it bends), four points a segment, none evaluated.
    for (const HermiteSegment& segment : segments) {
        box.add(view(segment.start + segment.start_tangent * (1.0 / 3.0)));
        box.add(view(segment.end - segment.end_tangent * (1.0 / 3.0)));
    }
    for (const ControlPoint& point : request.points)
        box.add(view(point.position));
    for (const Vec3& frame : request.frames)
        box.add(view(frame));
    return box;
}

} // namespace

std::string sif_path_document(const SifPathRequest& request)
{
    const ParallelView view(request.view);
    const std::vector<HermiteSegment> segments = kb_segments(request.points, request.slopes);
    const PlaneBox box = path_box(request, segments, view);
    const PlaneText plane(view, box.size());
    std::string text;
    text.reserve(request.points.size() * 700 + request.frames.size() * 120 + 2048);
    append_canvas_start(text, box, request.timing.fps, last_frame_of(request), request.name);
    append_left_out_comment(text, request);
    const double size = box.size();
    append_path_outline(text, request, segments, plane, size / 200.0);
    append_control_point_marks(text, request, plane, size / 120.0);
    append_circle(text, "the point", size / 60.0, moving_origin(request, plane), 1.0, 0.0);
    text += "</canvas>\n";
    return text;
}

std::string sif_animation_document(const SifAnimationRequest& request)
{
    const ParallelView view(request.view);
    PlaneBox box;
    for (std::size_t f = 0; f < request.frames.frame_count(); ++f)
        for (const Vec3& point : request.frames.frame(f))
            box.add(view(point));
    const PlaneText plane(view, box.size());
    std::string text;
    const long long last_frame =
        request.frames.frame_count() == 0 ? 0 : static_cast<long long>(request.frames.frame_count()) - 1;
    append_canvas_start(text, box, request.fps, last_frame, request.name);
    text += "  <!-- APCS's frames: frame 0 is KEY1, the last KEY2; each part's vertices move through the "
            "in-betweens, one linear waypoint a frame. -->\n";
    // Every frame lays its points out part after part, as the structure's parts hold them; a closed
    // part is a looped outline, whether or not a frame's first and last points meet.
    std::size_t first_point = 0;
    for (std::size_t part = 0; part < request.structure.parts.size(); ++part) {
        const GraphicPart& shape = request.structure.parts[part];
        if (first_point + shape.points.size() > request.frames.points_per_frame())
            break; // frames of another graphic: never from fit, which lays out the structure's points
        append_outline_start(text, shape.name.empty() ? "part " + std::to_string(part + 1) : shape.name,
                             shape.closure == Closure::closed);
        for (std::size_t vertex = first_point; vertex < first_point + shape.points.size(); ++vertex) {
            std::string point = "<animated type=\"vector\">\n";
            for (std::size_t f = 0; f < request.frames.frame_count(); ++f)
                append_linear_waypoint(point, plane, static_cast<long long>(f), plane.at(request.frames.frame(f)[vertex]),
                                       Precision::drawn, "        ");
            point += "      </animated>";
            append_bline_vertex(text, plane, point, {}, {});
        }
        append_outline_end(text, box.size() / 150.0, 0.0);
        first_point += shape.points.size();
    }
    text += "</canvas>\n";
    return text;
}

} // namespace apcs
