// apcs play's cost per frame against its delay (200 ms by default): the scene's frame evaluated
// (SceneAnimation::frame, what every frame would cost if computed on the fly), and the player's
// frame as the terminal shows it (tick, the 720x348 raster, cells at 80x24 and 200x60, the diff of
// the cells against the last frame), for the bicycle (73 frames, 5 objects) and the robot (13
// frames, 15 objects and 13 joints). Plus the one-off start: reading the scene and all its frames.
#include "cell_diff.h"

#include "apcs/raster/graphics_screen.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/formats/dat_file.h"
#include "apcs/scene/scene_file.h"
#include "apcs/playback/animation_player.h"
#include "apcs/base/step_log.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

using namespace apcs;

namespace {

const char* const scene_files[] = {"bicycle/bicycle.scn", "robot/robot.scn"};

Scene read_example(std::int64_t which)
{
    const std::filesystem::path file = std::filesystem::path(APCS_SOURCE_DIR) / "data" / scene_files[which];
    Expected<Scene> scene = read_scene_file(file, {});
    if (!scene) {
        std::cerr << scene.error().to_string() << '\n';
        std::exit(1);
    }
    return std::move(*scene);
}

PathSettings scene_settings()
{
    PathSettings settings;
    // Exact spacing, the dearer of the two: the numbers of docs/PERFORMANCE.md were measured with
    // it, apcs play's default for scenes until issue 44 (now nearest, or the scene's SPACING).
    settings.spacing = Spacing::exact;
    return settings;
}

void count_frames(benchmark::State& state, std::size_t frames_per_iteration)
{
    // Inverted rate: the time of one frame (the iteration's time divided by its frames).
    state.counters["per_frame"] = benchmark::Counter(static_cast<double>(frames_per_iteration),
                                                     benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

void scene_frame(benchmark::State& state)
{
    const Scene scene = read_example(state.range(0));
    const SceneAnimation animation(scene, scene_settings());
    std::vector<Vec3> points(animation.points_per_frame());
    for (auto _ : state)
        for (int f = 0; f <= animation.last_frame(); ++f) {
            animation.frame(f, points);
            benchmark::DoNotOptimize(points.data());
        }
    count_frames(state, animation.frame_count());
}

void play_frame(benchmark::State& state)
{
    const Scene scene = read_example(state.range(0));
    const SceneAnimation animation(scene, scene_settings());
    const CellArea area{static_cast<int>(state.range(1)), static_cast<int>(state.range(2))};
    const auto glyphs = static_cast<GlyphSet>(state.range(3));
    const FrameSequence frames = animation.all_frames();
    const ViewAngles angles = scene.view.value_or(ViewAngles{30, 40});
    UnloggedSteps log;
    AsciiGlyphCache cache;
    for (auto _ : state) {
        // The player is made once per play, before the first frame: not a frame's cost.
        state.PauseTiming();
        AnimationPlayer player(frames, animation.structure(), {"s", "s"}, angles, 200, log);
        CellGrid previous(area.columns, area.rows);
        state.ResumeTiming();
        while (player.playing()) {
            const CellGrid grid = render_cells(player.view(), area, glyphs, cache);
            benchmark::DoNotOptimize(bench::changed_cells(previous, grid));
            previous = grid;
            player.tick();
        }
    }
    count_frames(state, frames.frame_count());
}

void play_start(benchmark::State& state)
{
    for (auto _ : state) {
        const Scene scene = read_example(state.range(0));
        const SceneAnimation animation(scene, scene_settings());
        benchmark::DoNotOptimize(animation.all_frames().frame_count());
    }
}

// Issue 29's scale: OBJECTS objects of 100 points each (a ring of 50 in two parts), over FRAMES
// frames, every object with a MOVE along its own 4-point path, a ROTATE and a SCALE, ten of them
// parents of the rest. The scene is made in memory (one path file and one shape file).
Scene large_scene(int objects, int frames)
{
    std::string shape = "PART a\n";
    for (int k = 0; k < 100; ++k) {
        if (k == 50)
            shape += "PART b\n";
        const double angle = 2.0 * 3.141592653589793 * k / 50.0;
        shape += "0 " + std::to_string(std::cos(angle) + (k >= 50 ? 3 : 0)) + " " + std::to_string(std::sin(angle)) + "\n";
    }
    const std::string path = "0 0 0\n0 5 1\n0 9 -1\n0 14 0\n";
    std::string text = "FRAMES " + std::to_string(frames) + "\n";
    for (int i = 0; i < objects; ++i) {
        text += "OBJECT o" + std::to_string(i) + (i >= 10 ? " PARENT o" + std::to_string(i % 10) : "") + "\n";
        text += "SHAPE shape.dat\nMOVE path.dat\nROTATE 0.5\nSCALE 1.0001\n";
    }
    const SceneFileReader read = [&](const std::string& name) -> Expected<DatFile> {
        return parse_dat(name == "path.dat" ? path : shape, name, 1);
    };
    Expected<Scene> scene = parse_scene(text, "large.scn", read, {});
    if (!scene) {
        std::cerr << scene.error().to_string() << '\n';
        std::exit(1);
    }
    return std::move(*scene);
}

// Each frame of the large scene timed on its own: the median and the worst frame against the
// player's default delay of 200 ms (counters median_ms and worst_ms).
void large_scene_frames(benchmark::State& state)
{
    const Scene scene = large_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    const SceneAnimation animation(scene, scene_settings());
    std::vector<Vec3> points(animation.points_per_frame());
    std::vector<double> milliseconds;
    for (auto _ : state) {
        milliseconds.clear();
        for (int f = 0; f <= animation.last_frame(); ++f) {
            const auto start = std::chrono::steady_clock::now();
            animation.frame(f, points);
            benchmark::DoNotOptimize(points.data());
            milliseconds.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
    }
    std::sort(milliseconds.begin(), milliseconds.end());
    state.counters["median_ms"] = milliseconds[milliseconds.size() / 2];
    state.counters["worst_ms"] = milliseconds.back();
    state.counters["points"] = static_cast<double>(animation.points_per_frame());
}

// Reading the large scene and computing what every frame needs (MOVE offsets): the player's start.
void large_scene_start(benchmark::State& state)
{
    for (auto _ : state) {
        const Scene scene = large_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
        const SceneAnimation animation(scene, scene_settings());
        benchmark::DoNotOptimize(animation.points_per_frame());
    }
}

} // namespace

BENCHMARK(large_scene_frames)->ArgNames({"objects", "frames"})->Args({1000, 1000})->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(large_scene_start)->ArgNames({"objects", "frames"})->Args({1000, 1000})->Unit(benchmark::kMillisecond);

BENCHMARK(scene_frame)->ArgName("scene")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

BENCHMARK(play_frame)
    ->ArgNames({"scene", "columns", "rows", "glyphs"})
    ->Args({0, 80, 24, static_cast<int>(GlyphSet::ascii)})
    ->Args({0, 80, 24, static_cast<int>(GlyphSet::braille)})
    ->Args({0, 200, 60, static_cast<int>(GlyphSet::ascii)})
    ->Args({0, 200, 60, static_cast<int>(GlyphSet::braille)})
    ->Args({1, 80, 24, static_cast<int>(GlyphSet::ascii)})
    ->Args({1, 200, 60, static_cast<int>(GlyphSet::braille)})
    ->Unit(benchmark::kMillisecond);

BENCHMARK(play_start)->ArgName("scene")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
