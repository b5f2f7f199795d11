// Surface fitting at 10^3 … 10^6 points x 12 in-betweens: compute only, and with the
// in-between files written (to a temporary folder).
#include "apcs/animation/surface_fit.h"
#include "apcs/formats/inbetween_files.h"

#include <benchmark/benchmark.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include <cmath>
#include <filesystem>
#include <unistd.h>

using namespace apcs;

namespace {

Graphic wave(std::size_t points, double phase, double shift)
{
    Graphic graphic;
    graphic.parts.push_back({"wave", Closure::open, {}});
    graphic.parts[0].points.reserve(points);
    for (std::size_t i = 0; i < points; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(points);
        graphic.parts[0].points.push_back({shift, 10.0 * t, std::sin(20.0 * t + phase)});
    }
    return graphic;
}

ControlPoints path_between(const Vec3& from, const Vec3& to)
{
    return {{from, {}}, {(from + to) * 0.5 + Vec3{2, 1, 3}, {0.2, 0, 0, 0.3}}, {to, {}}};
}

struct FitInputs {
    EqualisedKeys keys;
    EvaluatedPath first;
    EvaluatedPath last;
};

FitInputs inputs(std::size_t points)
{
    FitInputs in{{wave(points, 0.0, 0.0), wave(points, 1.5, 8.0)}, {}, {}};
    const PathSettings settings{{}, 32, 12, Spacing::nearest};
    in.first = evaluate_path(path_between(in.keys.key1.parts[0].points.front(), in.keys.key2.parts[0].points.front()), settings);
    in.last = evaluate_path(path_between(in.keys.key1.parts[0].points.back(), in.keys.key2.parts[0].points.back()), settings);
    return in;
}

void fit_compute(benchmark::State& state)
{
    const FitInputs in = inputs(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(fit_key_frames(in.keys, in.first, in.last));
    state.SetItemsProcessed(state.iterations() * state.range(0) * 14);
    state.counters["points_x_frames"] = static_cast<double>(state.range(0) * 14);
}

// Fits and writes the in-betweens of `state.range(0)` points each iteration into new files (an
// unchanged file would only be compared) in a folder of its own, removed at the end.
void fit_and_write_with(benchmark::State& state, const std::string& name,
                        const std::function<void(const FitInputs&, const std::filesystem::path&)>& fit_and_write)
{
    const FitInputs in = inputs(static_cast<std::size_t>(state.range(0)));
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / (name + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    for (auto _ : state) {
        state.PauseTiming();
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            std::filesystem::remove(entry.path());
        state.ResumeTiming();
        fit_and_write(in, folder);
    }
    std::filesystem::remove_all(folder);
    state.SetItemsProcessed(state.iterations() * state.range(0) * 14);
}

void fit_and_write(benchmark::State& state)
{
    fit_and_write_with(state, "apcs-bench-", [](const FitInputs& in, const std::filesystem::path& folder) {
        const FrameSequence frames = fit_key_frames(in.keys, in.first, in.last);
        benchmark::DoNotOptimize(write_inbetween_files(frames, in.keys.key1, folder, KeyFileGuard{}));
    });
}

// What apcs fit does without --print or pictures: each in-between computed, formatted and
// written a chunk at a time, no frame held.
void fit_streamed_and_written(benchmark::State& state)
{
    fit_and_write_with(state, "apcs-bench-s", [](const FitInputs& in, const std::filesystem::path& folder) {
        std::array<std::vector<Vec3>, 2> storage;
        const SurfaceFitter fitter = key_frames_fitter(in.keys, in.first, in.last, storage);
        benchmark::DoNotOptimize(write_inbetween_files(fitter, in.keys.key1, folder, KeyFileGuard{}));
    });
}

// A path's in-betweens placed with nearest spacing (the thesis' Decide_Show_Inbetween): a
// three-segment path (as data/n-to-l/way1.dat) at --samples 2000, with range(0) in-betweens; each
// finds the sample nearest its target chord length.
void place_inbetweens_nearest(benchmark::State& state)
{
    const PathSettings settings{{}, 2000, static_cast<int>(state.range(0)), Spacing::nearest};
    const ControlPoints points{{{0, 0, 0}, {}}, {{3, 4, 1}, {0.2, 0, 0, 0.5}}, {{7, 3, 0}, {}}, {{10, 6, 2}, {}}};
    EvaluatedPath path = evaluate_path(points, settings);
    for (auto _ : state) {
        place_inbetweens(points, settings, path);
        benchmark::DoNotOptimize(path.inbetweens.data());
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

} // namespace

BENCHMARK(place_inbetweens_nearest)->Arg(600)->Arg(60000)->Unit(benchmark::kMillisecond);
BENCHMARK(fit_compute)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
BENCHMARK(fit_and_write)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(fit_streamed_and_written)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);
