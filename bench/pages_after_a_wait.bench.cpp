// One pass that writes the staff values (32 bytes) of each of 10^6 control points of 56 bytes,
// as a global key does, in 4 KB pages (std::allocator) and in 2 MB pages (LargeArrayAllocator),
// typed at once or 300 ms after the last pass (the wait not timed), as a person types. On a virtual
// machine the wait leaves the page-table walks cold (PERFORMANCE.md 9i). Arg: wait in ms.
#include "apcs/animation/control_point.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <thread>
#include <vector>

using namespace apcs;

namespace {

template <class Points>
void write_staff_values(benchmark::State& state)
{
    Points points(1'000'000);
    const auto wait = std::chrono::milliseconds(state.range(0));
    double value = 0.5;
    for (auto _ : state) {
        state.PauseTiming();
        std::this_thread::sleep_for(wait);
        value = -value;
        state.ResumeTiming();
        for (ControlPoint& point : points)
            point.staff = StaffValues{value, value, value, value};
        benchmark::DoNotOptimize(points.data());
        benchmark::ClobberMemory();
    }
}

void in_4k_pages(benchmark::State& state) { write_staff_values<std::vector<ControlPoint>>(state); }
void in_2m_pages(benchmark::State& state) { write_staff_values<ControlPoints>(state); }

} // namespace

BENCHMARK(in_4k_pages)->ArgName("wait_ms")->Arg(0)->Arg(300)->Iterations(10)->Unit(benchmark::kMillisecond);
BENCHMARK(in_2m_pages)->ArgName("wait_ms")->Arg(0)->Arg(300)->Iterations(10)->Unit(benchmark::kMillisecond);
