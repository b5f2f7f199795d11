// Reading a Synfig document's animated origin (SPEC §7.5): 10^5 TCB waypoints, one a frame, as
// Synfig 1.4 writes them (about 21 MB), and a document of 10^6 waypoints, the most a path holds.
// Writing one (apcs export) of a 10^5-point path with staff values, and reading it back.
#include "apcs/formats/sif_export.h"
#include "apcs/formats/sif_path.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>

using namespace apcs;

namespace {

std::string document_of(std::size_t waypoints)
{
    std::string text = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                       "<canvas version=\"1.2\" width=\"480\" height=\"270\" fps=\"24\">\n"
                       "  <layer type=\"circle\" active=\"true\" version=\"0.2\" desc=\"point\">\n"
                       "    <param name=\"origin\">\n      <animated type=\"vector\">\n";
    for (std::size_t i = 0; i < waypoints; ++i) {
        const std::string frame = std::to_string(i);
        text += "        <waypoint time=\"" + frame + "f\" before=\"auto\" after=\"auto\" tension=\"0.5\" "
                "continuity=\"0\" bias=\"-0.2\" temporal-tension=\"0\">\n          <vector><x>" + frame +
                ".0000000000</x><y>-" + frame + ".2500000000</y></vector>\n        </waypoint>\n";
    }
    return text + "      </animated>\n    </param>\n  </layer>\n</canvas>\n";
}

void read_waypoints(benchmark::State& state)
{
    const std::string text = document_of(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        Expected<SifPath> path = parse_sif_path(text, "walk.sif", {});
        if (!path) {
            state.SkipWithError(path.error().to_string().c_str());
            return;
        }
        benchmark::DoNotOptimize(path->file.parts[0].points.data());
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}

// A path of `count` control points on a wave, each with its own t c b.
ControlPoints wave_of(std::size_t count)
{
    ControlPoints points(count);
    for (std::size_t k = 0; k < count; ++k) {
        const double x = static_cast<double>(k);
        points[k] = {{x, std::sin(x / 7.0) * 5.0, 0.0}, {std::sin(x) / 2.0, std::cos(x) / 2.0, std::sin(x / 3.0) / 2.0, 0.0}};
    }
    return points;
}

void write_document(benchmark::State& state)
{
    const ControlPoints points = wave_of(static_cast<std::size_t>(state.range(0)));
    std::size_t bytes = 0;
    for (auto _ : state) {
        const std::string document = sif_path_document({points, {}, {-90.0, 0.0}, {}, SifMotion::tcb, {}, "wave.dat"});
        bytes = document.size();
        benchmark::DoNotOptimize(document.data());
    }
    state.counters["bytes"] = static_cast<double>(bytes);
}

void read_exported_document(benchmark::State& state)
{
    const ControlPoints points = wave_of(static_cast<std::size_t>(state.range(0)));
    const std::string document = sif_path_document({points, {}, {-90.0, 0.0}, {}, SifMotion::tcb, {}, "wave.dat"});
    for (auto _ : state) {
        Expected<SifPath> path = parse_sif_path(document, "wave.sif", {});
        if (!path) {
            state.SkipWithError(path.error().to_string().c_str());
            return;
        }
        benchmark::DoNotOptimize(path->file.parts[0].points.data());
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(document.size()));
}

// A layer whose description is `length` bytes long: read in pieces that grow with what expat holds
// unfinished, 32 MiB should cost about 8 times 4 MiB (pieces of a fixed 64 KiB: about 38 times).
void read_long_attribute(benchmark::State& state)
{
    const std::string text = "<?xml version=\"1.0\"?>\n<canvas version=\"1.2\">\n<layer desc=\"" +
                             std::string(static_cast<std::size_t>(state.range(0)), 'w') + "\"/>\n</canvas>\n";
    for (auto _ : state)
        benchmark::DoNotOptimize(parse_sif_path(text, "long.sif", {}));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}

} // namespace

BENCHMARK(read_long_attribute)->Arg(4 << 20)->Arg(32 << 20)->Unit(benchmark::kMillisecond);
BENCHMARK(write_document)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(read_exported_document)->Arg(100'000)->Unit(benchmark::kMillisecond);
BENCHMARK(read_waypoints)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
