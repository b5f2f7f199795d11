// One staff keystroke on a path of 10^4, 10^5 and 10^6 control points, as the session's path
// editor takes it (update, then the screen's raster mapped to 80x24 ASCII cells): TENSION under
// global control (every span changes), TENSION under local control of control points 1 to 5, and
// ACCELERATION under global control (the spacing only). How the cost grows with the points.
#include "apcs/raster/graphics_screen.h"
#include "apcs/session/command.h"
#include "apcs/session/path_editor.h"
#include "apcs/session/session_log.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <initializer_list>

using namespace apcs;

namespace {

enum class KeyKind { global_tension, local_tension, global_acceleration };

PathEditor::Setup long_path(std::size_t count)
{
    PathEditor::Setup setup;
    setup.path_name = "way1.dat";
    for (std::size_t k = 0; k < count; ++k) {
        const double t = static_cast<double>(k);
        setup.points.push_back({{std::sin(t * 0.9) * 3.0, t * 2.0, std::cos(t * 0.7) * 4.0}, {}});
    }
    return setup;
}

void apply(PathEditor& editor, std::initializer_list<Command> commands)
{
    for (const Command& command : commands)
        editor.update(command);
}

void staff_key_on_long_path(benchmark::State& state)
{
    UnloggedSteps log;
    PathEditor editor(long_path(static_cast<std::size_t>(state.range(0))), log);
    switch (static_cast<KeyKind>(state.range(1))) {
    case KeyKind::global_tension:
        apply(editor, {command::ChooseGlobal{}});
        break;
    case KeyKind::local_tension:
        // The arrow's first move brings it to control point 1; Enter there and again four points on.
        apply(editor, {command::ChooseLocal{}, command::ArrowMove{1}, command::Accept{}, command::ArrowMove{4},
                       command::Accept{}});
        break;
    case KeyKind::global_acceleration:
        apply(editor, {command::ChooseGlobal{}, command::Accept{}, command::Accept{}, command::Accept{}});
        break;
    }
    if (editor.phase() != SessionPhase::staff) {
        state.SkipWithError("the editor is not on the staff: the key would change nothing");
        return;
    }
    AsciiGlyphCache cache;
    int step = 1;
    for (auto _ : state) {
        step = -step; // back and forth, so the value stays inside −1 … 1
        editor.update(command::StaffStep{step});
        benchmark::DoNotOptimize(render_cells(editor.view(), {80, 24}, GlyphSet::ascii, cache));
    }
}

} // namespace

BENCHMARK(staff_key_on_long_path)
    ->ArgNames({"points", "key"})
    ->ArgsProduct({{10'000, 100'000, 1'000'000},
                   {static_cast<int>(KeyKind::global_tension), static_cast<int>(KeyKind::local_tension),
                    static_cast<int>(KeyKind::global_acceleration)}})
    ->Unit(benchmark::kMillisecond);
