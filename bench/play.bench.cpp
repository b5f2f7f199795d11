// apcs play's cost per frame against its delay (200 ms by default): the scene's frame evaluated
// (SceneAnimation::frame, what every frame would cost if computed on the fly), and the player's
// frame as the terminal shows it (tick, the 720x348 raster, cells at 80x24 and 200x60, the diff of
// the cells against the last frame), for the bicycle (73 frames, 5 objects) and the robot (13
// frames, 15 objects and 13 joints). Plus the one-off start: reading the scene and all its frames.
#include "cell_diff.h"

#include "apcs/raster/graphics_screen.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"
#include "apcs/session/animation_player.h"
#include "apcs/session/session_log.h"

#include <benchmark/benchmark.h>

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
    settings.spacing = Spacing::exact; // apcs play's default for scenes
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

} // namespace

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
