// The path editor's chart (path_editor_chart.cpp): every command the key map lets through in each
// of its leaves, and the overlays hand to the step, meets a row or a written ignore; every row can
// be met; the chart as printed is the newcomer's map (tests/golden/path_editor_chart.txt).
#include "apcs/editor/path_editor.h"
#include "apcs/input/overlays.h"

#include "support/golden.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;

namespace {

using State = PathEditor::State;

// "staff --StaffStep" for each leaf and command of the key map there that the overlays leave to
// the editor and no row of `chart` answers.
std::vector<std::string> gaps(const PathEditor::EditorChart& chart)
{
    std::vector<std::string> missing;
    for (const auto& state : chart.states()) {
        if (!chart.is_leaf(state.state))
            continue;
        const KeyContext keys = PathEditor::key_context_of(state.state);
        for (const KeyBinding& binding : key_bindings()) {
            if (!binding.contexts.contains(keys))
                continue;
            Overlays overlays;
            if (overlays.handle(keys, binding.command, {QuitAsks::question_first, {}}) != OverlayAnswer::step_command)
                continue;
            if (!chart.answers(state.state, binding.command.index()))
                missing.push_back(std::string(state.name) + " --" + std::string(command_name(binding.command.index())));
        }
    }
    return missing;
}

} // namespace

TEST_CASE("every command the key map lets through to the path editor meets a row or a written ignore in every leaf",
          "[editor][chart]")
{
    REQUIRE(gaps(PathEditor::chart()).empty());
}

TEST_CASE("the coverage walk fails when a row that alone answers a command is removed", "[editor][chart]")
{
    const PathEditor::EditorChart& chart = PathEditor::chart();
    int alone = 0;
    for (std::size_t index = 0; index < chart.rows().size(); ++index) {
        const auto& row = chart.rows()[index];
        const PathEditor::EditorChart without = chart.without_row(index);
        bool still_answered = true;
        for (const auto& state : chart.states())
            if (chart.is_leaf(state.state) && chart.encloses(row.from, state.state) &&
                !without.answers(state.state, row.event))
                still_answered = false;
        if (still_answered)
            continue; // a guarded row, or one a parent's row stands behind
        ++alone;
        CAPTURE(chart.info(row.from).name, command_name(row.event));
        CHECK_FALSE(gaps(without).empty());
    }
    // Most rows answer their command alone: the walk is not vacuous.
    REQUIRE(alone >= 20);
}

TEST_CASE("every row of the path editor's chart can be met: no row stands behind another for good", "[editor][chart]")
{
    const PathEditor::EditorChart& chart = PathEditor::chart();
    for (std::size_t index = 0; index < chart.rows().size(); ++index) {
        CAPTURE(chart.info(chart.rows()[index].from).name, command_name(chart.rows()[index].event));
        CHECK(chart.reachable(index));
    }
}

TEST_CASE("among a state's rows for one command the last has no guard", "[editor][chart]")
{
    const PathEditor::EditorChart& chart = PathEditor::chart();
    const auto rows = chart.rows();
    for (std::size_t index = 0; index < rows.size(); ++index) {
        bool later = false;
        for (std::size_t other = index + 1; other < rows.size(); ++other)
            later = later || (rows[other].from == rows[index].from && rows[other].event == rows[index].event);
        if (!later) {
            CAPTURE(chart.info(rows[index].from).name, command_name(rows[index].event));
            CHECK(rows[index].guard == nullptr);
        }
    }
}

TEST_CASE("the path editor's chart, printed one row a line, is the approved map", "[editor][chart]")
{
    test::check_golden("path_editor_chart.txt", PathEditor::chart().printed());
}
