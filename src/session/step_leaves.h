#pragma once

#include "apcs/base/variant_index.h"
#include "apcs/session/session.h"

#include <array>
#include <variant>

// Which leaf of the session's chart each step is, in one table: the step types are what a step
// holds, the chart's leaves what it is called and listens with.
namespace apcs::session_leaves {

using State = Session::State;

// In Step's order (session_steps.h).
inline constexpr std::array<State, std::variant_size_v<Step>> of_step = {
    State::ask_key1,      State::ask_key2, State::splitting, State::ask_view, State::ask_path_file, State::ask_slopes,
    State::path_screen,   State::ask_next_path, State::ask_stop, State::ask_draw, State::player, State::finished,
};

template <typename Kind>
inline constexpr State of = of_step[variant_index<Step, Kind>()];

static_assert(of<step::Shaping> == State::path_screen && of<step::Playing> == State::player &&
                  of<step::Finished> == State::finished && of<step::Key1Prompt> == State::ask_key1,
              "of_step in Step's order");

} // namespace apcs::session_leaves
