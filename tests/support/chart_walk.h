#pragma once

// The walk over a chart (input/chart.h) that proves it whole: every command the key map lets
// through in each leaf meets a row, a written ignore, or a row handing it to a chart of its own.
#include "apcs/input/chart.h"
#include "apcs/input/key_map.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace apcs::test {

// The commands the key map sends in `keys`, each once, in the key map's order.
inline std::vector<std::size_t> commands_sent(KeyContext keys)
{
    std::vector<std::size_t> events;
    for (const KeyBinding& binding : key_bindings()) {
        const std::size_t event = binding.command.index();
        if (binding.contexts.contains(keys) && std::find(events.begin(), events.end(), event) == events.end())
            events.push_back(event);
    }
    return events;
}

// "staff --StaffStep" for each leaf and command that no row of `chart` answers; `events_of(leaf)`
// gives the commands the leaf is sent.
template <typename Machine, typename State, typename EventsOf>
std::vector<std::string> chart_gaps(const Chart<Machine, State>& chart, EventsOf events_of)
{
    std::vector<std::string> missing;
    for (const auto& state : chart.states())
        if (chart.is_leaf(state.state))
            for (const std::size_t event : events_of(state.state))
                if (!chart.answers(state.state, event))
                    missing.push_back(std::string(state.name) + " --" + std::string(command_name(event)));
    return missing;
}

// The walk written out, one line a leaf and command it is sent: the rows the command meets, in the
// order their guards are tried ("staff + Accept: staff [the last line] -> ask_again, else staff ->
// staff"), so that a row removed or shadowed changes the approved file even where a row of a state
// around would still answer.
template <typename Machine, typename State, typename EventsOf>
std::string chart_walk_text(const Chart<Machine, State>& chart, EventsOf events_of)
{
    std::string text;
    for (const auto& state : chart.states()) {
        if (!chart.is_leaf(state.state))
            continue;
        for (const std::size_t event : events_of(state.state)) {
            text += std::string(state.name) + " + " + std::string(command_name(event)) + ":";
            const auto met = chart.candidates(state.state, event);
            for (const auto* row : met) {
                if (row != met.front())
                    text += ", else";
                text += " " + std::string(chart.info(row->from).name);
                if (row->guard)
                    text += " [" + std::string(row->guard_name) + "]";
                if (row->event == any_other_event)
                    text += " (any other)";
                text += row->ignores() ? " ignored"
                                       : " -> " + (row->to ? std::string(chart.info(*row->to).name) : std::string("(stays)"));
            }
            text += chart.answers(state.state, event) ? "\n" : " NOTHING\n";
        }
    }
    return text;
}

// How many of the chart's rows alone answer a command sent in some leaf below them (no other row,
// nor a row of a state around, stands behind them): the rows whose removal chart_gaps would find.
// A chart whose walk finds no gap and many such rows is proved row by row, not by a catch-all.
template <typename Machine, typename State, typename EventsOf>
int rows_alone(const Chart<Machine, State>& chart, EventsOf events_of)
{
    int alone = 0;
    for (std::size_t index = 0; index < chart.rows().size(); ++index) {
        const auto& row = chart.rows()[index];
        const Chart<Machine, State> without = chart.without_row(index);
        bool still_answered = true;
        for (const auto& state : chart.states())
            if (chart.is_leaf(state.state) && chart.encloses(row.from, state.state))
                for (const std::size_t event : events_of(state.state))
                    if ((row.event == event || row.event == any_other_event) && chart.candidates(state.state, event).back() == &row &&
                        !without.answers(state.state, event))
                        still_answered = false;
        alone += still_answered ? 0 : 1;
    }
    return alone;
}

// Every row can be met, and among a state's rows for one event the last has no guard.
template <typename Machine, typename State, typename Event>
void check_rows_met_and_guards_end(const Chart<Machine, State, Event>& chart)
{
    const auto rows = chart.rows();
    for (std::size_t index = 0; index < rows.size(); ++index) {
        CAPTURE(chart.info(rows[index].from).name, chart.event_name(rows[index].event));
        CHECK(chart.reachable(index));
        bool later = false;
        for (std::size_t other = index + 1; other < rows.size(); ++other)
            later = later || (rows[other].from == rows[index].from && rows[other].event == rows[index].event);
        if (!later)
            CHECK(rows[index].guard == nullptr);
    }
}

} // namespace apcs::test
