// Reading and writing a .dat file of 10^6 points, and the start of a session up to its first
// prompt (the session object and its first screen; the terminal's own start-up is not counted).
#include "apcs/formats/dat_file.h"
#include "apcs/formats/file_io.h"
#include "apcs/session/session.h"
#include "apcs/session/session_files.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <unistd.h>

using namespace apcs;

namespace {

DatFile million_points()
{
    DatFile file;
    file.parts.push_back({"cloud", Closure::open, {}});
    file.parts[0].points.reserve(1000000);
    for (int i = 0; i < 1000000; ++i)
        file.parts[0].points.push_back({{i * 0.001, (i % 977) * 0.37, (i % 131) * -1.25}, std::nullopt, 0});
    return file;
}

std::filesystem::path bench_file(const char* name)
{
    return std::filesystem::temp_directory_path() / (std::string(name) + std::to_string(::getpid()) + ".dat");
}

void write_million(benchmark::State& state)
{
    const DatFile file = million_points();
    const auto target = bench_file("apcs-write-");
    for (auto _ : state) {
        std::filesystem::remove(target);
        benchmark::DoNotOptimize(write_file_atomically(target, format_dat(file)));
    }
    std::filesystem::remove(target);
    std::filesystem::remove(backup_path_for(target));
}

void read_million(benchmark::State& state)
{
    const auto target = bench_file("apcs-read-");
    const Expected<WriteResult> written = write_file_atomically(target, format_dat(million_points()));
    if (!written) {
        state.SkipWithError(written.error().to_string().c_str());
        return;
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(read_dat_file(target));
    std::filesystem::remove(target);
}

void session_first_prompt(benchmark::State& state)
{
    MemoryFiles files;
    for (auto _ : state) {
        Session session({}, files);
        benchmark::DoNotOptimize(session.screen());
    }
}

} // namespace

BENCHMARK(write_million)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(read_million)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(session_first_prompt)->Unit(benchmark::kMicrosecond);
