// The path editor on a path of 10^4, 10^5 and 10^6 control points, as the session takes its keys
// (update, then the screen's raster mapped to 80x24 ASCII cells): a staff key — TENSION under
// global control (every span changes), TENSION under local control of control points 1 to 5, and
// ACCELERATION under global control (the spacing only) — with nearest and with exact spacing; a
// waypoint-editor key (a point moved, inserted, deleted, in the middle of the path); and opening the
// path to its first picture. How the cost grows with the points. The paths: a long trajectory
// (along y, small wiggles in x and z) and a scribble (consecutive points across the screen).
// The *_in_steps cases take the terminal's way (Refinement::in_steps, path_picture.h): the time to
// the first picture (the key or the opening, and its screen), and to the final one (then every
// refinement step until none is left, and the screen again); each key starts from a refined picture.
#include "apcs/raster/graphics_screen.h"
#include "apcs/input/command.h"
#include "apcs/editor/path_editor.h"
#include "apcs/base/step_log.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <initializer_list>
#include <thread>

using namespace apcs;

namespace {

enum class KeyKind { global_tension, local_tension, global_acceleration };
enum class WaypointKey { move, insert, remove };
enum class Shape { trajectory, scribble };
// first_picture_after_a_wait: the first picture of a key typed 300 ms after the last picture was
// finished, as a person types (the wait not timed). On a virtual machine the wait leaves the
// page-table walks cold, which a key typed at once does not show (PERFORMANCE.md 9i).
enum class Until { first_picture, final_picture, first_picture_after_a_wait };

PathEditor::Setup long_path(std::size_t count, Spacing spacing, Shape shape = Shape::trajectory,
                            Refinement refinement = Refinement::at_once)
{
    PathEditor::Setup setup;
    setup.path_name = "way1.dat";
    setup.settings.spacing = spacing;
    setup.refinement.when = refinement;
    for (std::size_t k = 0; k < count; ++k) {
        const double t = static_cast<double>(k);
        const double along = shape == Shape::trajectory ? t * 2.0 : t * 1e-6;
        setup.points.push_back({{std::sin(t * 0.9) * 3.0, along, std::cos(t * 0.7) * (shape == Shape::trajectory ? 4.0 : 0.01)}, {}});
    }
    return setup;
}

void apply(PathEditor& editor, std::initializer_list<Command> commands)
{
    for (const Command& command : commands)
        editor.update(command);
}

void show(const PathEditor& editor, AsciiGlyphCache& cache)
{
    benchmark::DoNotOptimize(render_cells(editor.view(), {80, 24}, GlyphSet::ascii, cache));
}

void go_to_staff(PathEditor& editor, KeyKind kind)
{
    switch (kind) {
    case KeyKind::global_tension: apply(editor, {command::ChooseGlobal{}}); break;
    case KeyKind::local_tension:
        // The arrow's first move brings it to control point 1; Enter there and again four points on.
        apply(editor, {command::ChooseLocal{}, command::ArrowMove{1}, command::Accept{}, command::ArrowMove{4},
                       command::Accept{}});
        break;
    case KeyKind::global_acceleration:
        apply(editor, {command::ChooseGlobal{}, command::Accept{}, command::Accept{}, command::Accept{}});
        break;
    }
}

void staff_key(benchmark::State& state, Shape shape)
{
    UnloggedSteps log;
    PathEditor editor(long_path(static_cast<std::size_t>(state.range(0)), static_cast<Spacing>(state.range(2)), shape),
                      log);
    go_to_staff(editor, static_cast<KeyKind>(state.range(1)));
    if (editor.leaf() != PathEditor::State::staff) {
        state.SkipWithError("the editor is not on the staff: the key would change nothing");
        return;
    }
    AsciiGlyphCache cache;
    int step = 1;
    for (auto _ : state) {
        step = -step; // back and forth, so the value stays inside −1 … 1
        editor.update(command::StaffStep{step});
        show(editor, cache);
    }
}

void staff_key_on_long_path(benchmark::State& state) { staff_key(state, Shape::trajectory); }
void staff_key_on_scribble(benchmark::State& state) { staff_key(state, Shape::scribble); }

void refine_all(PathEditor& editor)
{
    while (editor.refining())
        editor.refine_step();
}

// The key's first picture, or its final one after every step (args: points, key, spacing, until).
void staff_key_in_steps(benchmark::State& state, Shape shape)
{
    UnloggedSteps log;
    PathEditor editor(long_path(static_cast<std::size_t>(state.range(0)), static_cast<Spacing>(state.range(2)), shape,
                                Refinement::in_steps),
                      log);
    go_to_staff(editor, static_cast<KeyKind>(state.range(1)));
    refine_all(editor);
    if (editor.leaf() != PathEditor::State::staff) {
        state.SkipWithError("the editor is not on the staff: the key would change nothing");
        return;
    }
    const auto until = static_cast<Until>(state.range(3));
    AsciiGlyphCache cache;
    int step = 1;
    for (auto _ : state) {
        step = -step;
        editor.update(command::StaffStep{step});
        show(editor, cache);
        if (until == Until::final_picture) {
            refine_all(editor);
            show(editor, cache);
        } else {
            state.PauseTiming();
            refine_all(editor);
            if (until == Until::first_picture_after_a_wait)
                std::this_thread::sleep_for(std::chrono::milliseconds(300));
            state.ResumeTiming();
        }
    }
}

void staff_key_in_steps_on_long_path(benchmark::State& state) { staff_key_in_steps(state, Shape::trajectory); }
void staff_key_in_steps_on_scribble(benchmark::State& state) { staff_key_in_steps(state, Shape::scribble); }

// A key in the waypoint editor on the middle control point; an insertion or deletion is undone (U,
// not timed) before the next, so the path keeps its size.
void waypoint_key(benchmark::State& state, Shape shape)
{
    const auto points = static_cast<std::size_t>(state.range(0));
    UnloggedSteps log;
    PathEditor editor(long_path(points, Spacing::nearest, shape), log);
    apply(editor, {command::OpenWaypoints{}, command::ChoosePoint{static_cast<int>(points / 2)}});
    if (editor.leaf() != PathEditor::State::waypoints) {
        state.SkipWithError("the waypoint editor is not open");
        return;
    }
    AsciiGlyphCache cache;
    const auto key = static_cast<WaypointKey>(state.range(1));
    int step = 1;
    for (auto _ : state) {
        step = -step;
        if (key == WaypointKey::move)
            editor.update(command::MovePoint{step, 0, step});
        else
            editor.update(key == WaypointKey::insert ? Command{command::InsertPoint{}} : Command{command::DeletePoint{}});
        show(editor, cache);
        if (key != WaypointKey::move) {
            state.PauseTiming();
            editor.update(command::Undo{});
            state.ResumeTiming();
        }
    }
    if (editor.points().size() != points)
        state.SkipWithError("the path did not keep its size");
}

void waypoint_key_on_long_path(benchmark::State& state) { waypoint_key(state, Shape::trajectory); }
void waypoint_key_on_scribble(benchmark::State& state) { waypoint_key(state, Shape::scribble); }

// Opening: the editor evaluates the path, fits the view and draws the first picture (the points
// are made before the clock starts, as a file read would have made them); the terminal's way
// (Refinement::in_steps), to the first picture or to the final one.
void open_path(benchmark::State& state, Refinement refinement, Until until)
{
    const PathEditor::Setup setup = long_path(static_cast<std::size_t>(state.range(0)), static_cast<Spacing>(state.range(1)),
                                              Shape::trajectory, refinement);
    AsciiGlyphCache cache;
    for (auto _ : state) {
        state.PauseTiming();
        PathEditor::Setup copy = setup;
        state.ResumeTiming();
        UnloggedSteps log;
        PathEditor editor(std::move(copy), log);
        show(editor, cache);
        if (until == Until::final_picture) {
            refine_all(editor);
            show(editor, cache);
        }
    }
}

void open_long_path(benchmark::State& state) { open_path(state, Refinement::at_once, Until::first_picture); }
// Args: points, spacing, until.
void open_long_path_in_steps(benchmark::State& state)
{
    open_path(state, Refinement::in_steps, static_cast<Until>(state.range(2)));
}

constexpr int nearest = static_cast<int>(Spacing::nearest);
constexpr int exact = static_cast<int>(Spacing::exact);
constexpr int first_picture = static_cast<int>(Until::first_picture);
constexpr int final_picture = static_cast<int>(Until::final_picture);
constexpr int after_a_wait = static_cast<int>(Until::first_picture_after_a_wait);

} // namespace

BENCHMARK(staff_key_on_long_path)
    ->ArgNames({"points", "key", "spacing"})
    ->ArgsProduct({{10'000, 100'000, 1'000'000},
                   {static_cast<int>(KeyKind::global_tension), static_cast<int>(KeyKind::local_tension),
                    static_cast<int>(KeyKind::global_acceleration)},
                   {nearest, exact}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(staff_key_on_scribble)
    ->ArgNames({"points", "key", "spacing"})
    ->ArgsProduct({{1'000'000},
                   {static_cast<int>(KeyKind::global_tension), static_cast<int>(KeyKind::local_tension),
                    static_cast<int>(KeyKind::global_acceleration)},
                   {nearest}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(waypoint_key_on_long_path)
    ->ArgNames({"points", "key"})
    ->ArgsProduct({{10'000, 100'000, 1'000'000},
                   {static_cast<int>(WaypointKey::move), static_cast<int>(WaypointKey::insert),
                    static_cast<int>(WaypointKey::remove)}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(waypoint_key_on_scribble)
    ->ArgNames({"points", "key"})
    ->ArgsProduct({{1'000'000},
                   {static_cast<int>(WaypointKey::move), static_cast<int>(WaypointKey::insert),
                    static_cast<int>(WaypointKey::remove)}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(staff_key_in_steps_on_long_path)
    ->ArgNames({"points", "key", "spacing", "until"})
    ->ArgsProduct({{1'000'000},
                   {static_cast<int>(KeyKind::global_tension), static_cast<int>(KeyKind::local_tension),
                    static_cast<int>(KeyKind::global_acceleration)},
                   {nearest, exact},
                   {first_picture, final_picture, after_a_wait}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(staff_key_in_steps_on_scribble)
    ->ArgNames({"points", "key", "spacing", "until"})
    ->ArgsProduct({{1'000'000},
                   {static_cast<int>(KeyKind::global_tension), static_cast<int>(KeyKind::local_tension)},
                   {nearest},
                   {first_picture, final_picture}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(open_long_path_in_steps)
    ->ArgNames({"points", "spacing", "until"})
    ->ArgsProduct({{1'000'000}, {nearest, exact}, {first_picture, final_picture}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

BENCHMARK(open_long_path)
    ->ArgNames({"points", "spacing"})
    ->ArgsProduct({{1'000'000}, {nearest, exact}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
