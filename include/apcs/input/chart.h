#pragma once

#include "apcs/base/variant_index.h"
#include "apcs/input/command.h"
#include "apcs/input/key_map.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

// A small statechart, after boost-ext/sml's one transition table: states in a tree (a parent is
// tried when a leaf has no row for an event), rows `From --Event[guard] / action--> To` whose events
// are Command's alternatives (or a chart's own: the session's steps' outcomes), a written ignore
// where a key means nothing in a state, and what leaving a state does. The machine keeps its own
// data (its modes); the chart says which row an event meets and prints itself.
namespace apcs {

// The name of Command's alternative `index`, as the printed chart writes an event: "StaffStep".
std::string_view command_name(std::size_t index);

// A row's event: `on<command::StaffStep>`.
template <typename Event>
inline constexpr std::size_t on = variant_index<Command, Event>();

// A row's event that every event meets which no row of its state, nor of a state around it, takes:
// a state whose other events go to a chart of their own (the path screen's to the path editor's).
inline constexpr std::size_t any_other_event = std::numeric_limits<std::size_t>::max();

// How a chart numbers and names its events: Command's alternatives, unless a chart says otherwise
// (the session's steps end in outcomes, session_steps.h).
template <typename Event>
struct ChartEvents;

template <>
struct ChartEvents<Command> {
    static std::size_t index(const Command& command) { return command.index(); }
    static std::string_view name(std::size_t index) { return command_name(index); }
};

template <typename Machine, typename State>
struct ChartState {
    State state;
    std::string_view name;
    std::optional<State> parent; // none: the root
    // The keys the state listens with (key_map.h); none: its parent's.
    std::optional<KeyContext> keys = {};
    // What a transcript and the help screen call the step ("step 4: four-line staff"); empty: its
    // parent's.
    std::string_view title = {};
    // What leaving the state does (the machine already in the state it goes to); none: nothing.
    std::string_view exit_name = {};
    void (*on_exit)(Machine&) = nullptr;
};

template <typename Machine, typename State, typename Event = Command>
struct ChartRow {
    State from;
    std::size_t event = 0; // ChartEvents<Event>::index, or any_other_event
    std::string_view guard_name = {};
    bool (*guard)(const Machine&, const Event&) = nullptr; // none: always
    // What the row does; a written ignore has no action and says here why the key means nothing.
    std::string_view action_name = {};
    void (*action)(Machine&, const Event&) = nullptr;
    std::optional<State> to = {}; // none: the machine stays in the state it is in
    bool ignores() const { return action == nullptr; }
};

template <typename Machine, typename State, typename Event = Command>
class Chart {
public:
    using Row = ChartRow<Machine, State, Event>;
    using StateInfo = ChartState<Machine, State>;
    using Events = ChartEvents<Event>;

    // `states` lists every state once, a parent before its children; among a state's rows for one
    // event, the last has no guard (the chart's "else").
    Chart(std::vector<StateInfo> states, std::vector<Row> rows) : m_states(std::move(states)), m_rows(std::move(rows))
    {
    }

    // The rows `event` may meet in `leaf`, in the order their guards are tried: the leaf's rows for
    // it, then its parent's, up to the root, then the rows for any other event the same way; ending
    // at the first without a guard. `visit(row)` sees each until it returns true; returns that row,
    // or none.
    template <typename Visit>
    const Row* find_candidate(State leaf, std::size_t event, Visit visit) const
    {
        for (const std::size_t wanted : {event, any_other_event})
            for (std::optional<State> state = leaf; state; state = info(*state).parent)
                for (const Row& row : m_rows) {
                    if (row.from != *state || row.event != wanted)
                        continue;
                    if (visit(row))
                        return &row;
                    if (!row.guard)
                        return nullptr;
                }
        return nullptr;
    }

    // The same rows, all of them (empty: none).
    std::vector<const Row*> candidates(State leaf, std::size_t event) const
    {
        std::vector<const Row*> met;
        find_candidate(leaf, event, [&met](const Row& row) {
            met.push_back(&row);
            return false;
        });
        return met;
    }

    // The row `event` meets in `leaf`: the first candidate whose guard holds; none when no state
    // on the way has a row for it. Every key asks it: it walks the rows without keeping them.
    const Row* row_for(const Machine& machine, State leaf, const Event& event) const
    {
        return find_candidate(leaf, Events::index(event),
                              [&](const Row& row) { return !row.guard || row.guard(machine, event); });
    }

    // The row met, taken: its action, then what leaving does for every state around `leaf` that is
    // not around the state the machine is in afterwards (`now`, read once the action has run).
    template <typename Now>
    void take(Machine& machine, State leaf, const Row& row, const Event& event, Now now) const
    {
        if (row.ignores())
            return;
        row.action(machine, event);
        const State after = now(machine);
        assert(!row.to || encloses(*row.to, after));
        for (std::optional<State> state = leaf; state; state = info(*state).parent)
            if (!encloses(*state, after) && info(*state).on_exit)
                info(*state).on_exit(machine);
    }

    // `event` in the machine's leaf (`now`): the row it meets taken, if any; whether there was one.
    template <typename Now>
    bool fire(Machine& machine, const Event& event, Now now) const
    {
        const State leaf = now(machine);
        const Row* row = row_for(machine, leaf, event);
        if (row != nullptr)
            take(machine, leaf, *row, event, now);
        return row != nullptr;
    }

    // `state`, else the nearest state around it, for which `holds(info)`; none if no state does.
    template <typename Holds>
    const StateInfo* nearest(State state, Holds holds) const
    {
        for (std::optional<State> around = state; around; around = info(*around).parent)
            if (holds(info(*around)))
                return &info(*around);
        return nullptr;
    }

    // The keys `state` listens with: its own, else the nearest state's around it that names them.
    std::optional<KeyContext> keys(State state) const
    {
        const StateInfo* naming = nearest(state, [](const StateInfo& around) { return around.keys.has_value(); });
        return naming != nullptr ? naming->keys : std::nullopt;
    }

    // What a transcript calls `state`: its title, else the nearest one around it.
    std::string_view title(State state) const
    {
        const StateInfo* titled = nearest(state, [](const StateInfo& around) { return !around.title.empty(); });
        return titled != nullptr ? titled->title : std::string_view();
    }

    // The chart `make` builds, built once (a room's chart() accessor).
    template <Chart (*make)()>
    static const Chart& once()
    {
        static const Chart chart = make();
        return chart;
    }

    static std::string_view event_name(std::size_t event)
    {
        return event == any_other_event ? std::string_view("(any other)") : Events::name(event);
    }

    // Whether `outer` is `state` or one of its parents.
    bool encloses(State outer, State state) const
    {
        return nearest(state, [outer](const StateInfo& around) { return around.state == outer; }) != nullptr;
    }

    // Whether `event` meets a row in `leaf` whatever the guards say: its candidates end unguarded.
    bool answers(State leaf, std::size_t event) const
    {
        const std::vector<const Row*> met = candidates(leaf, event);
        return !met.empty() && !met.back()->guard;
    }

    // Whether row `index` can be met: it is a candidate in some leaf.
    bool reachable(std::size_t index) const
    {
        const Row& target = m_rows[index];
        for (const StateInfo& leaf : m_states) {
            if (!is_leaf(leaf.state))
                continue;
            // An event no row names meets the rows for any other event alone.
            const std::size_t probe = target.event == any_other_event ? any_other_event - 1 : target.event;
            const std::vector<const Row*> met = candidates(leaf.state, probe);
            if (std::find(met.begin(), met.end(), &target) != met.end())
                return true;
        }
        return false;
    }

    bool is_leaf(State state) const
    {
        for (const StateInfo& other : m_states)
            if (other.parent == state)
                return false;
        return true;
    }

    const StateInfo& info(State state) const
    {
        for (const StateInfo& known : m_states)
            if (known.state == state)
                return known;
        assert(false && "a state the chart does not list");
        return m_states.front();
    }

    std::span<const StateInfo> states() const { return m_states; }
    std::span<const Row> rows() const { return m_rows; }

    // The same chart without row `index` (the coverage test's check that it notices).
    Chart without_row(std::size_t index) const
    {
        std::vector<Row> rows = m_rows;
        rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(index));
        return Chart(m_states, std::move(rows));
    }

    // The states as a tree, then printed_rows().
    std::string printed() const
    {
        std::string text;
        for (const StateInfo& state : m_states) {
            text += "state " + std::string(state.name);
            if (state.parent)
                text += " in " + std::string(info(*state.parent).name);
            if (state.keys)
                text += ", keys " + std::string(key_context_name(*state.keys));
            if (!state.title.empty())
                text += ", \"" + std::string(state.title) + "\"";
            if (state.on_exit)
                text += ", on leaving: " + std::string(state.exit_name);
            text += '\n';
        }
        return text + printed_rows();
    }

    // One row a line: "staff --Accept[last line] / log the line--> ask_again", "(stays)" for a row
    // that leaves the machine where it is, "ignored: WHY" for a written ignore.
    std::string printed_rows() const
    {
        std::string text;
        for (const Row& row : m_rows) {
            text += std::string(info(row.from).name) + " --" + std::string(event_name(row.event));
            if (row.guard)
                text += "[" + std::string(row.guard_name) + "]";
            if (row.ignores()) {
                text += " / ignored: " + std::string(row.action_name) + '\n';
                continue;
            }
            text += " / " + std::string(row.action_name) + "--> " +
                    (row.to ? std::string(info(*row.to).name) : std::string("(stays)")) + '\n';
        }
        return text;
    }

private:
    std::vector<StateInfo> m_states;
    std::vector<Row> m_rows;
};

} // namespace apcs
