// The session's chart (session_chart.cpp), the path editor's (path_editor_chart.cpp) and the
// animation player's (animation_player_chart.cpp), with the steps' graph (session_graph.cpp) and
// the replay's rows around them (replay_rows.cpp): every command the key map lets through in each
// leaf meets a row, a written ignore, or the row handing it to the editor's or the player's chart,
// whose leaves meet it in turn; the walk fails when a row that alone answers a command is removed;
// every row can be met; a state's last row for an event has no guard; and all of it, printed with
// what each command meets in each leaf, is the newcomer's map (tests/golden/session_chart.txt): a
// row removed or shadowed changes it even where a row of a state around would still answer.
#include "apcs/editor/path_editor.h"
#include "apcs/lesson/replay_rows.h"
#include "apcs/playback/animation_player.h"
#include "apcs/session/session.h"

#include "support/chart_walk.h"
#include "support/golden.h"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace apcs;

namespace {

using Leaf = Session::State;

// The commands the session hands from `screen` (path_screen, player) to its own chart: those that
// meet the row for any other there.
std::vector<std::size_t> handed_down(Leaf screen, KeyContext keys)
{
    std::vector<std::size_t> events;
    for (const std::size_t event : test::commands_sent(keys)) {
        const auto met = Session::chart().candidates(screen, event);
        if (!met.empty() && met.back()->event == any_other_event)
            events.push_back(event);
    }
    return events;
}

// Every command any leaf of `chart` listens for: what the session's leaf for that screen is sent.
template <typename Machine, typename State>
std::vector<std::size_t> sent_to_any_leaf(const Chart<Machine, State>& chart)
{
    std::vector<std::size_t> events;
    for (const auto& state : chart.states())
        if (chart.is_leaf(state.state))
            for (const std::size_t event : test::commands_sent(*chart.keys(state.state)))
                if (std::find(events.begin(), events.end(), event) == events.end())
                    events.push_back(event);
    return events;
}

std::vector<std::size_t> session_events(Leaf leaf)
{
    if (leaf == Leaf::path_screen)
        return sent_to_any_leaf(PathEditor::chart());
    if (leaf == Leaf::player)
        return sent_to_any_leaf(AnimationPlayer::chart());
    return test::commands_sent(*Session::chart().keys(leaf));
}

std::vector<std::size_t> editor_events(PathEditor::State leaf)
{
    return handed_down(Leaf::path_screen, *PathEditor::chart().keys(leaf));
}

std::vector<std::size_t> player_events(AnimationPlayer::State leaf)
{
    return handed_down(Leaf::player, *AnimationPlayer::chart().keys(leaf));
}

// `least_alone`: how many rows at least answer their command alone (the walk is not vacuous).
template <typename Machine, typename State, typename EventsOf>
std::string checked_chart(const Chart<Machine, State>& chart, EventsOf events_of, int least_alone)
{
    CHECK(test::chart_gaps(chart, events_of).empty());
    CHECK(test::rows_alone(chart, events_of) >= least_alone);
    test::check_rows_met_and_guards_end(chart);
    return chart.printed() + "\nThe walk: what each command the keys send meets in each leaf\n" +
           test::chart_walk_text(chart, events_of);
}

std::string replay_printed()
{
    std::string text;
    for (const ReplayRow& row : replay_rows()) {
        text += std::string(replay_state_name(row.state)) + " --" + std::string(replay_key_name(row.key));
        if (row.guard != ReplayGuard::always)
            text += "[" + std::string(replay_guard_name(row.guard)) + "]";
        text += " / " + std::string(replay_action_name(row.action)) + "\n";
    }
    for (const ReplayIgnore& ignore : replay_ignores())
        text += std::string(replay_state_name(ignore.state)) + " --" + std::string(replay_key_name(ignore.key)) +
                " / ignored: " + std::string(ignore.why) + "\n";
    return text;
}

} // namespace

TEST_CASE("the session's chart, with the path editor's and the player's below it, answers every command its keys "
          "send in every leaf, each row can be met and counts, and it prints as approved",
          "[session][chart]")
{
    std::string map = "# The session (src/session/session_chart.cpp)\n"
                      "# A row to `steps` leaves the step to say how it ended: the steps' graph, below, says which "
                      "step follows (or none: the step stays).\n" +
                      checked_chart(Session::chart(), session_events, 12);
    test::check_rows_met_and_guards_end(Session::graph());
    map += "\n# The steps' graph: how a step ended, the step that follows (src/session/session_graph.cpp)\n" +
           Session::graph().printed_rows();
    map += "\n# path_screen: the path editor (src/editor/path_editor_chart.cpp)\n" +
           checked_chart(PathEditor::chart(), editor_events, 20);
    map += "\n# player: the animation player (src/playback/animation_player_chart.cpp)\n" +
           checked_chart(AnimationPlayer::chart(), player_events, 5);
    map += "\n# The replay around the session: its state, the key as it tells keys apart "
           "(src/lesson/replay_rows.cpp)\n" +
           replay_printed();
    test::check_golden("session_chart.txt", map);
}

TEST_CASE("the session keeps ?, P and q for itself and hands every other command the path screen's and the "
          "animation's keys send to their charts",
          "[session][chart]")
{
    const std::vector<std::size_t> kept = {on<command::ShowHelp>, on<command::SavePicture>, on<command::Quit>};
    const auto check_handed = [&](Leaf screen, KeyContext keys) {
        std::vector<std::size_t> expected;
        for (const std::size_t event : test::commands_sent(keys))
            if (std::find(kept.begin(), kept.end(), event) == kept.end())
                expected.push_back(event);
        CAPTURE(key_context_name(keys));
        CHECK(handed_down(screen, keys) == expected);
    };
    for (const auto& state : PathEditor::chart().states())
        if (PathEditor::chart().is_leaf(state.state))
            check_handed(Leaf::path_screen, *PathEditor::chart().keys(state.state));
    for (const auto& state : AnimationPlayer::chart().states())
        if (AnimationPlayer::chart().is_leaf(state.state))
            check_handed(Leaf::player, *AnimationPlayer::chart().keys(state.state));
}

TEST_CASE("every step of the session is a leaf of its chart with a title, and the keys of a leaf without a chart of "
          "its own",
          "[session][chart]")
{
    const Session::SessionChart& chart = Session::chart();
    for (const auto& state : chart.states()) {
        if (!chart.is_leaf(state.state) || state.state == Leaf::path_screen || state.state == Leaf::player)
            continue;
        CAPTURE(state.name);
        CHECK(chart.keys(state.state).has_value());
        if (chart.encloses(Leaf::steps, state.state))
            CHECK_FALSE(chart.title(state.state).empty());
    }
    for (const auto& state : PathEditor::chart().states())
        if (PathEditor::chart().is_leaf(state.state))
            CHECK_FALSE(PathEditor::chart().title(state.state).empty());
    for (const auto& state : AnimationPlayer::chart().states())
        if (AnimationPlayer::chart().is_leaf(state.state))
            CHECK_FALSE(AnimationPlayer::chart().title(state.state).empty());
}
