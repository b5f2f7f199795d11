// The steps' graph, a chart whose events are how a step ended (boost-ext/sml's make_transition_table
// is the model): the step on the screen, its outcome, the step that follows. How each step is made
// from the one before it is that step's `after` (session_steps.h): a row without one does not
// compile. Quitting (q, or Y to a quit question) goes from any step to the end by the session's
// chart (session_chart.cpp).
#include "apcs/session/session.h"

#include "step_leaves.h"

#include <array>
#include <type_traits>

namespace apcs {

std::string_view ChartEvents<StepResult>::name(std::size_t index)
{
    constexpr std::array<std::string_view, 7> names = {"stay", "answered", "refused", "stopped",
                                                       "done", "first_path_accepted", "last_path_accepted"};
    static_assert(static_cast<std::size_t>(StepOutcome::last_path_accepted) == names.size() - 1,
                  "a name for every outcome, in StepOutcome's order");
    return index < names.size() ? names[index] : "?";
}

// The step `To`, made from `From` before `From` is gone; made in place, as steps that keep a
// reference (to the log) cannot be assigned.
template <typename From, typename To>
void Session::make_step_after()
{
    StepContext step_context = context();
    To made = To::after(std::get<From>(m_step), step_context);
    m_step.emplace<To>(std::move(made));
}

namespace {

using State = Session::State;
using Graph = Session::StepGraph;
using enum StepOutcome;
using session_leaves::of;

} // namespace

const Session::StepGraph& Session::graph() { return StepGraph::once<&make_graph>(); }

Session::StepGraph Session::make_graph()
{
    // `From` ended with `outcome`: `To` follows, made from it.
    const auto row = []<typename From, typename To>(StepOutcome outcome, std::string_view what) -> Graph::Row {
        return {of<From>, static_cast<std::size_t>(outcome), {}, nullptr, what,
                [](Session& s, const StepResult&) { s.make_step_after<From, To>(); }, of<To>};
    };
    using namespace step;
    std::vector<Graph::Row> rows = {
        // Step 1: the key frames, then the split into path files.
        row.operator()<Key1Prompt, Key2Prompt>(answered, "KEY1 read"),
        row.operator()<Key1Prompt, Key1Prompt>(refused, "asked again"),
        row.operator()<Key2Prompt, Splitting>(answered, "KEY2 read, the points made equal"),
        row.operator()<Key2Prompt, Key2Prompt>(refused, "asked again"),
        row.operator()<Splitting, ViewPrompt>(done, "every path file written"),
        row.operator()<Splitting, Key2Prompt>(stopped, "the files written stay, KEY2 asked again"),
        row.operator()<Splitting, Key2Prompt>(refused, "a write failed: KEY2 asked again"),
        // Step 2: the view.
        row.operator()<ViewPrompt, PathPrompt>(answered, "the view and delay set: the first path's file"),
        row.operator()<ViewPrompt, ViewPrompt>(refused, "asked again"),
        // Steps 3-5: each of the two paths read, its slopes, shaped in graphics mode.
        row.operator()<PathPrompt, SlopesPrompt>(answered, "the path read"),
        row.operator()<PathPrompt, PathPrompt>(refused, "asked again"),
        row.operator()<SlopesPrompt, Shaping>(answered, "the slopes set: graphics mode"),
        row.operator()<SlopesPrompt, SlopesPrompt>(refused, "asked again"),
        row.operator()<Shaping, AskNext>(first_path_accepted, "the first path written"),
        row.operator()<AskNext, PathPrompt>(answered, "the last path's file"),
        row.operator()<Shaping, AskStop>(last_path_accepted, "the last path written"),
        // Step 6: surface fitting, the animation, the end.
        row.operator()<AskStop, Fitted>(answered, "the in-betweens fitted and written"),
        row.operator()<Fitted, AskStop>(refused, "a write failed: asked again"),
        row.operator()<Fitted, Playing>(answered, "the animation"),
        row.operator()<Playing, Finished>(done, "the files written listed"),
    };
    const auto states = chart().states();
    return StepGraph({states.begin(), states.end()}, std::move(rows));
}

} // namespace apcs
