#pragma once

// The walk over a chart (input/chart.h) that proves it whole: every command the key map lets
// through in each leaf, and the overlays hand to the step, meets a row or a written ignore.
#include "apcs/input/chart.h"
#include "apcs/input/key_map.h"
#include "apcs/input/overlays.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace apcs::test {

// The commands the key map sends in `keys` that the overlays hand to the step, each once, in the
// key map's order.
inline std::vector<std::size_t> step_events(KeyContext keys)
{
    std::vector<std::size_t> events;
    for (const KeyBinding& binding : key_bindings()) {
        const std::size_t event = binding.command.index();
        Overlays overlays;
        if (binding.contexts.contains(keys) &&
            overlays.handle(keys, binding.command, {QuitAsks::question_first, {}}) == OverlayAnswer::step_command &&
            std::find(events.begin(), events.end(), event) == events.end())
            events.push_back(event);
    }
    return events;
}

// "staff --StaffStep" for each leaf and command that no row of `chart` answers; `keys_of(leaf)`
// gives the key context the leaf listens with.
template <typename Machine, typename State, typename KeysOf>
std::vector<std::string> chart_gaps(const Chart<Machine, State>& chart, KeysOf keys_of)
{
    std::vector<std::string> missing;
    for (const auto& state : chart.states())
        if (chart.is_leaf(state.state))
            for (const std::size_t event : step_events(keys_of(state.state)))
                if (!chart.answers(state.state, event))
                    missing.push_back(std::string(state.name) + " --" + std::string(command_name(event)));
    return missing;
}

// The walk written out, one line a leaf and command the key map sends there: the rows the command
// meets, in the order their guards are tried ("staff --Accept: [the last line] -> ask_again, else
// -> staff"), so that a row removed or shadowed changes the approved file even where a row of a
// state around would still answer.
template <typename Machine, typename State, typename KeysOf>
std::string chart_walk_text(const Chart<Machine, State>& chart, KeysOf keys_of)
{
    std::string text;
    for (const auto& state : chart.states()) {
        if (!chart.is_leaf(state.state))
            continue;
        for (const std::size_t event : step_events(keys_of(state.state))) {
            text += std::string(state.name) + " + " + std::string(command_name(event)) + ":";
            const auto met = chart.candidates(state.state, event);
            for (const auto* row : met) {
                if (row != met.front())
                    text += ", else";
                text += " " + std::string(chart.info(row->from).name);
                if (row->guard)
                    text += " [" + std::string(row->guard_name) + "]";
                text += row->ignores() ? " ignored"
                                       : " -> " + (row->to ? std::string(chart.info(*row->to).name) : std::string("(stays)"));
            }
            text += chart.answers(state.state, event) ? "\n" : " NOTHING\n";
        }
    }
    return text;
}

// The chart's rows that alone answer their command in some leaf below them (no other row, nor a
// row of a state around, stands behind them): removing one must leave a gap the walk finds.
// Returns how many there are.
template <typename Machine, typename State, typename KeysOf>
int check_rows_alone_leave_gaps(const Chart<Machine, State>& chart, KeysOf keys_of)
{
    int alone = 0;
    for (std::size_t index = 0; index < chart.rows().size(); ++index) {
        const auto& row = chart.rows()[index];
        const Chart<Machine, State> without = chart.without_row(index);
        bool still_answered = true;
        for (const auto& state : chart.states())
            if (chart.is_leaf(state.state) && chart.encloses(row.from, state.state) &&
                !without.answers(state.state, row.event))
                still_answered = false;
        if (still_answered)
            continue;
        ++alone;
        CAPTURE(chart.info(row.from).name, command_name(row.event));
        CHECK_FALSE(chart_gaps(without, keys_of).empty());
    }
    return alone;
}

// Every row can be met, and among a state's rows for one command the last has no guard.
template <typename Machine, typename State>
void check_rows_met_and_guards_end(const Chart<Machine, State>& chart)
{
    const auto rows = chart.rows();
    for (std::size_t index = 0; index < rows.size(); ++index) {
        CAPTURE(chart.info(rows[index].from).name, command_name(rows[index].event));
        CHECK(chart.reachable(index));
        bool later = false;
        for (std::size_t other = index + 1; other < rows.size(); ++other)
            later = later || (rows[other].from == rows[index].from && rows[other].event == rows[index].event);
        if (!later)
            CHECK(rows[index].guard == nullptr);
    }
}

} // namespace apcs::test
