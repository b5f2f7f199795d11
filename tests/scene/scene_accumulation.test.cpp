// T_f as Net_Anim's accumulation (SPEC §8.2), held frame by frame to a simulation of the SPEC's
// formulas written here apart from the code: the face-on plane as complex numbers y + iz, the body
// as an angle and a factor (every turn of these scenes is about x, every scale uniform).
#include "scene/scene_test_support.h"

#include "apcs/scene/scene_animation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <vector>

using namespace apcs;
using apcs::test::DatFiles;
using apcs::test::scene_from;

namespace {

using Plane = std::complex<double>;

constexpr double degree = 3.14159265358979323846 / 180.0;

Plane in_plane(const Vec3& point) { return {point.y, point.z}; }
Vec3 in_scene(const Plane& point) { return {0.0, point.real(), point.imag()}; }

PathSettings exact_settings()
{
    PathSettings settings;
    settings.spacing = Spacing::exact;
    return settings;
}

// What one object does, in the simulation's terms.
struct Behaviours {
    std::vector<Plane> move_offsets; // P(s(f)) − P_0 per frame (empty: no MOVE)
    std::vector<double> align_angles; // ALIGN's turn per frame, radians (empty: no ALIGN)
    Plane align_pivot;               // P_0
    std::optional<std::pair<double, Plane>> rotate; // radians a frame, about
    std::optional<std::pair<double, Plane>> scale;  // factor a frame, about
    std::optional<std::pair<double, Plane>> roll;   // radius, hub
};

// Net_Anim's state of the object: its centre, its body's angle and factor.
struct SimulatedState {
    Plane centre;
    double angle = 0.0;
    double factor = 1.0;
};

// A point of the frame-0 drawing where `state` puts it.
Plane place(const SimulatedState& state, Plane centre0, Plane point)
{
    return state.centre + state.factor * std::polar(1.0, state.angle) * (point - centre0);
}

// The turns (radians, about) and scale of one tick, ROLL's left out.
struct SimulatedTick {
    Plane move;
    std::vector<std::pair<double, Plane>> turns;
    std::optional<std::pair<double, Plane>> scale;
};

// SPEC §8.2: every change from the state before the tick, summed; offsets carried with the body.
SimulatedState apply(const SimulatedState& before, Plane centre0, const SimulatedTick& tick)
{
    const Plane body = before.factor * std::polar(1.0, before.angle);
    SimulatedState after = before;
    after.centre += tick.move;
    for (const auto& [angle, about] : tick.turns) {
        const Plane r = body * (about - centre0);
        after.centre += (std::polar(1.0, angle) - 1.0) * -r;
        after.angle += angle;
    }
    if (tick.scale) {
        const Plane s = body * (tick.scale->second - centre0);
        after.centre += (1.0 - tick.scale->first) * s;
        after.factor *= tick.scale->first;
    }
    return after;
}

// A top-level object's states, frames 0 … last.
std::vector<SimulatedState> simulate(const Behaviours& behaviours, Plane centre0, int last)
{
    std::vector<SimulatedState> states{SimulatedState{centre0}};
    for (int f = 1; f <= last; ++f) {
        const auto k = static_cast<std::size_t>(f);
        SimulatedTick tick;
        if (!behaviours.move_offsets.empty())
            tick.move = behaviours.move_offsets[k] - behaviours.move_offsets[k - 1];
        if (!behaviours.align_angles.empty())
            tick.turns.push_back({behaviours.align_angles[k] - behaviours.align_angles[k - 1], behaviours.align_pivot});
        if (behaviours.rotate)
            tick.turns.push_back(*behaviours.rotate);
        tick.scale = behaviours.scale;
        const SimulatedState& before = states.back();
        if (behaviours.roll) {
            // The world turn changes by −(the hub's travel)/RADIUS: the travel and the other turns
            // taken from the tick without the roll.
            const auto [radius, hub] = *behaviours.roll;
            const SimulatedState others = apply(before, centre0, tick);
            const Plane travel = place(others, centre0, hub) - place(before, centre0, hub);
            const double distance = travel.real() < 0 ? -std::abs(travel) : std::abs(travel);
            tick.turns.push_back({-distance / radius - (others.angle - before.angle), hub});
        }
        states.push_back(apply(before, centre0, tick));
    }
    return states;
}

// MOVE's offsets and ALIGN's angles as the code finds them on `path`: a probe of two points, P_0
// and P_0 + (0, 1, 0), with that MOVE alone (its frames are the path's, checked by the MOVE and
// ALIGN tests), the inputs of the accumulation.
void probe_move(DatFiles files, const std::string& move_line, Plane pivot, int last, Behaviours& behaviours)
{
    files.texts["probe.dat"] = "0 " + std::to_string(pivot.real()) + " " + std::to_string(pivot.imag()) + "\n0 " +
                               std::to_string(pivot.real() + 1) + " " + std::to_string(pivot.imag()) + "\n";
    const Scene scene = scene_from("FRAMES " + std::to_string(last) + "\nOBJECT p\nSHAPE probe.dat\n" + move_line + "\n", files);
    const SceneAnimation animation(scene, exact_settings());
    const bool align = move_line.find("ALIGN") != std::string::npos;
    behaviours.align_pivot = pivot;
    for (int f = 0; f <= last; ++f) {
        const std::vector<Vec3> points = animation.frame(f);
        behaviours.move_offsets.push_back(in_plane(points[0]) - pivot);
        if (align)
            behaviours.align_angles.push_back(std::arg(in_plane(points[1]) - in_plane(points[0])));
    }
    for (std::size_t k = 1; k < behaviours.align_angles.size(); ++k) // unwrapped
        behaviours.align_angles[k] = behaviours.align_angles[k - 1] +
                                     std::remainder(behaviours.align_angles[k] - behaviours.align_angles[k - 1], 2 * 3.14159265358979323846);
}

// One behaviour line of a scene and what it is in the simulation.
struct Line {
    std::string kind; // MOVE, ROTATE, SCALE or ROLL: one of each kind per object
    std::string text;
    void (*set)(Behaviours&);
};

const Plane square_centre{2.0, 1.0};

DatFiles square_files()
{
    DatFiles files;
    files.texts["square.dat"] = "0 1 0\n0 3 0\n0 3 2\n0 1 2\n"; // centre (0, 2, 1)
    files.texts["arc.dat"] = "0 2 1\n0 6 3\n0 10 1\n";        // starts at the centre
    files.texts["far-arc.dat"] = "0 0 -1\n0 4 1\n0 8 -1\n";   // starts at another point
    return files;
}

// Every behaviour about the object's own centre and about another point.
std::vector<Line> behaviour_lines()
{
    return {
        {"MOVE", "MOVE arc.dat", nullptr},
        {"MOVE", "MOVE arc.dat ALIGN", nullptr},
        {"MOVE", "MOVE far-arc.dat ALIGN", nullptr},
        {"ROTATE", "ROTATE 10", [](Behaviours& b) { b.rotate = {{10 * degree, square_centre}}; }},
        {"ROTATE", "ROTATE 10 ABOUT 0 5 -1", [](Behaviours& b) { b.rotate = {{10 * degree, Plane{5, -1}}}; }},
        {"SCALE", "SCALE 1.1", [](Behaviours& b) { b.scale = {{1.1, square_centre}}; }},
        {"SCALE", "SCALE 1.1 ABOUT 0 -1 3", [](Behaviours& b) { b.scale = {{1.1, Plane{-1, 3}}}; }},
        {"ROTATE", "ROLL 1.5", [](Behaviours& b) { b.roll = {{1.5, square_centre}}; }},
        {"ROTATE", "ROLL 1.5 ABOUT 0 2.5 1", [](Behaviours& b) { b.roll = {{1.5, Plane{2.5, 1}}}; }},
    };
}

// The largest distance, over frames 0 … last, of the square's points from the simulation's.
double off_the_simulation(const std::vector<Line>& lines, int last)
{
    DatFiles files = square_files();
    std::string text = "FRAMES " + std::to_string(last) + "\nOBJECT square\nSHAPE square.dat\n";
    Behaviours behaviours;
    for (const Line& line : lines) {
        text += line.text + "\n";
        if (line.set)
            line.set(behaviours);
        else
            probe_move(files, line.text, line.text.find("far-arc") != std::string::npos ? Plane{0, -1} : square_centre,
                       last, behaviours);
    }
    const Scene scene = scene_from(text, files);
    const SceneAnimation animation(scene, exact_settings());
    const std::vector<SimulatedState> states = simulate(behaviours, square_centre, last);
    const std::vector<Vec3> drawing = animation.frame(0);
    double worst = 0.0;
    for (int f = 0; f <= last; ++f) {
        const std::vector<Vec3> points = animation.frame(f);
        for (std::size_t p = 0; p < points.size(); ++p)
            worst = std::max(worst, distance(points[p], in_scene(place(states[static_cast<std::size_t>(f)], square_centre,
                                                                            in_plane(drawing[p])))));
    }
    return worst;
}

} // namespace

TEST_CASE("a 2x2 square turned about one point and scaled about another is the seed's tick - 0.052 and 0.416 off "
          "the closed form at frames 1 and 3",
          "[scene][accumulation]")
{
    DatFiles files;
    files.texts["square.dat"] = "0 -1 -1\n0 1 -1\n0 1 1\n0 -1 1\n";
    const Scene scene =
        scene_from("FRAMES 3\nOBJECT square\nSHAPE square.dat\nROTATE 10 ABOUT 0 5 0\nSCALE 1.1 ABOUT 0 0 3\n", files);
    const SceneAnimation animation(scene, exact_settings());
    Behaviours behaviours;
    behaviours.rotate = {{10 * degree, Plane{5, 0}}};
    behaviours.scale = {{1.1, Plane{0, 3}}};
    const std::vector<SimulatedState> states = simulate(behaviours, Plane{}, 3);
    const std::vector<Vec3> drawing = animation.frame(0);
    const double expected_off[] = {0.0, 0.0523, 0.1792, 0.4161}; // from the closed form, 4 decimals
    for (int f = 0; f <= 3; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> points = animation.frame(f);
        // The composition built before: the turn about (0, 5, 0) after the scale about (0, 0, 3).
        const Affine closed = Affine::rotation_about(10.0 * f, Axis::x, {0, 5, 0}) *
                              Affine::scale_about(std::pow(1.1, f), Vec3{0, 0, 3});
        for (std::size_t p = 0; p < points.size(); ++p) {
            const Vec3 seed = in_scene(place(states[static_cast<std::size_t>(f)], Plane{}, in_plane(drawing[p])));
            REQUIRE(distance(points[p], seed) < 1e-12);
            REQUIRE(std::abs(distance(points[p], closed(drawing[p])) - expected_off[f]) < 5e-5);
        }
    }
}

TEST_CASE("every pair of behaviours about the object's centre and about another point is the simulated tick in "
          "every frame",
          "[scene][accumulation]")
{
    const std::vector<Line> lines = behaviour_lines();
    int pairs = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        CAPTURE(lines[i].text);
        CHECK(off_the_simulation({lines[i]}, 12) < 1e-9);
        for (std::size_t j = i + 1; j < lines.size(); ++j) {
            if (lines[j].kind == lines[i].kind)
                continue; // one behaviour of each kind, one ROTATE or ROLL
            CAPTURE(lines[j].text);
            CHECK(off_the_simulation({lines[i], lines[j]}, 12) < 1e-9);
            ++pairs;
        }
    }
    // MOVE (plain, ALIGN at the centre, ALIGN elsewhere) with the six others, ROTATE with SCALE
    // and SCALE with ROLL, each at the centre and elsewhere.
    REQUIRE(pairs == 3 * 6 + 4 + 4);
}

TEST_CASE("ROLL turns a part in the world by its hub's travel over RADIUS under its parent's ALIGN", "[scene][roll]")
{
    DatFiles files = square_files();
    files.texts["wheel.dat"] = "0 3 1\n0 2 2\n0 1 1\n0 2 0\n"; // a rim of radius 1 about (0, 2, 1)
    const Scene scene = scene_from("FRAMES 20\nOBJECT bike\nMOVE far-arc.dat ALIGN\n"
                                   "OBJECT wheel PARENT bike\nSHAPE wheel.dat\nROLL 1\n",
                                   files);
    const SceneAnimation animation(scene, exact_settings());
    double travelled = 0.0;
    double turned = 0.0;
    std::vector<Vec3> before = animation.frame(0);
    for (int f = 1; f <= 20; ++f) {
        CAPTURE(f);
        const std::vector<Vec3> now = animation.frame(f);
        const Vec3 hub_now = (now[0] + now[2]) * 0.5;
        const Vec3 hub_then = (before[0] + before[2]) * 0.5;
        travelled += distance(hub_now, hub_then) * (hub_now.y < hub_then.y ? -1.0 : 1.0);
        const Plane arm_now = in_plane(now[0] - hub_now);
        const Plane arm_then = in_plane(before[0] - hub_then);
        turned += std::arg(arm_now / arm_then);
        REQUIRE(std::abs(turned + travelled) < 1e-9); // clockwise face-on going +y: negative
        before = now;
    }
    REQUIRE(travelled > 5.0);
}
