// The session's whole graph in one table (boost-ext/sml's make_transition_table is the model):
// the step on the screen, how it ended, the step that follows. How each step is made from the one
// before it is that step's `after` (session_steps.h): a row without one does not compile.
#include "apcs/session/session_graph.h"

#include <algorithm>
#include <cassert>
#include <type_traits>

namespace apcs {

namespace {

template <typename T, typename Variant>
struct IndexIn;

template <typename T, typename... Alternatives>
struct IndexIn<T, std::variant<Alternatives...>> {
    static constexpr std::size_t value = [] {
        constexpr bool same[] = {std::is_same_v<T, Alternatives>...};
        return static_cast<std::size_t>(std::find(std::begin(same), std::end(same), true) - std::begin(same));
    }();
    static_assert(value < sizeof...(Alternatives), "not a step of the session");
};

template <typename T>
constexpr std::size_t step_index = IndexIn<T, Step>::value;

struct Transition {
    std::size_t from;
    StepOutcome outcome;
    Step (*next)(Step& from, StepContext& context);
};

template <typename From, StepOutcome outcome, typename To>
constexpr Transition row()
{
    return {step_index<From>, outcome,
            [](Step& from, StepContext& context) -> Step { return To::after(std::get<From>(from), context); }};
}

using namespace step;
using enum StepOutcome;

// Quitting (q, or Y to a quit question: after q on the path screen, after Esc on an empty prompt)
// goes from any step to Finished, outside this table.
constexpr Transition session_graph[] = {
    // Step 1: the key frames, then the split into path files.
    row<Key1Prompt, answered, Key2Prompt>(),
    row<Key1Prompt, refused, Key1Prompt>(),
    row<Key2Prompt, answered, Splitting>(),
    row<Key2Prompt, refused, Key2Prompt>(),
    row<Splitting, done, ViewPrompt>(),
    row<Splitting, stopped, Key2Prompt>(),
    row<Splitting, refused, Key2Prompt>(),
    // Step 2: the view.
    row<ViewPrompt, answered, PathPrompt>(),
    row<ViewPrompt, refused, ViewPrompt>(),
    // Steps 3–5: each of the two paths read, its slopes, shaped in graphics mode.
    row<PathPrompt, answered, SlopesPrompt>(),
    row<PathPrompt, refused, PathPrompt>(),
    row<SlopesPrompt, answered, Shaping>(),
    row<SlopesPrompt, refused, SlopesPrompt>(),
    row<Shaping, first_path_accepted, AskNext>(),
    row<AskNext, answered, PathPrompt>(),
    row<Shaping, last_path_accepted, AskStop>(),
    // Step 6: surface fitting, the animation, the end.
    row<AskStop, answered, Fitted>(),
    row<Fitted, refused, AskStop>(),
    row<Fitted, answered, Playing>(),
    row<Playing, done, Finished>(),
};

} // namespace

std::optional<Step> next_step(Step& from, StepOutcome outcome, StepContext& context)
{
    const auto found = std::find_if(std::begin(session_graph), std::end(session_graph), [&](const Transition& row) {
        return row.from == from.index() && row.outcome == outcome;
    });
    assert(found != std::end(session_graph) && "a step ended in a way the session's graph does not know");
    if (found == std::end(session_graph))
        return std::nullopt;
    return found->next(from, context);
}

} // namespace apcs
