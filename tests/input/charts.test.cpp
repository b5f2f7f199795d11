// The charts of the text console's steps (session_console_chart.cpp), the path editor
// (path_editor_chart.cpp) and the animation player (animation_player_chart.cpp): every command the key map lets through in each leaf, and the
// overlays hand to the step, meets a row or a written ignore; the walk fails when a row that alone
// answers a command is removed; every row can be met; a state's last row for a command has no
// guard; the chart as printed, with what each command meets in each leaf, is the newcomer's map
// (tests/golden/NAME_chart.txt): a row removed or shadowed changes it even where a row of a state
// around would still answer.
#include "apcs/editor/path_editor.h"
#include "apcs/playback/animation_player.h"
#include "apcs/session/session.h"

#include "support/chart_walk.h"
#include "support/golden.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

namespace {

// `least_alone`: how many rows at least answer their command alone (the walk is not vacuous).
template <typename Machine, typename State, typename KeysOf>
void check_chart(const Chart<Machine, State>& chart, KeysOf keys_of, const std::string& golden, int least_alone)
{
    REQUIRE(test::chart_gaps(chart, keys_of).empty());
    REQUIRE(test::check_rows_alone_leave_gaps(chart, keys_of) >= least_alone);
    test::check_rows_met_and_guards_end(chart);
    test::check_golden(golden, chart.printed() + "\nThe walk: what each command the keys send meets in each leaf\n" +
                                   test::chart_walk_text(chart, keys_of));
}

} // namespace

TEST_CASE("the path editor's chart answers every command its keys send in every leaf, each row can be met and "
          "counts, and it prints as approved",
          "[editor][chart]")
{
    check_chart(PathEditor::chart(), PathEditor::key_context_of, "path_editor_chart.txt", 20);
}

TEST_CASE("the animation player's chart answers every command its keys send in every leaf, each row can be met and "
          "counts, and it prints as approved",
          "[playback][chart]")
{
    check_chart(AnimationPlayer::chart(), AnimationPlayer::key_context_of, "animation_player_chart.txt", 5);
}

TEST_CASE("the text console's chart answers every command its keys send in every leaf, each row can be met and "
          "counts, and it prints as approved",
          "[session][chart]")
{
    check_chart(Session::console_chart(), Session::key_context_of, "session_console_chart.txt", 5);
}
