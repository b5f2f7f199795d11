// Reading a Synfig document's animated origin (SPEC §7.5): 10^5 TCB waypoints, one a frame, as
// Synfig 1.4 writes them (about 21 MB), and a document of 10^6 waypoints, the most a path holds.
#include "apcs/formats/sif_path.h"

#include <benchmark/benchmark.h>

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

} // namespace

BENCHMARK(read_waypoints)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
