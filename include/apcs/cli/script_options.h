#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/cli/options.h"
#include "apcs/formats/key_event.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace apcs {

// The session's options that shape what its keys do, which a key script may carry on its OPTIONS
// line (key_event.h): with another staff step, in-between count or spacing the same keys reach
// other values, so a recording made with them rechecks and grades only with them too. The
// options that choose how the session looks (--glyphs, --color, --pixels) or where it reads and
// writes (--workdir, --png, --record ...) are never a script's.
inline constexpr std::array<std::string_view, 13> carried_option_names{
    "--tension", "--continuity", "--bias",  "--accel", "--slopes", "--samples", "--spacing",
    "--surface", "--inbetweens", "--theta", "--phi",   "--delay",  "--step"};

// Of those, the ones that set an exercise's task: where the staff starts, the curve and what a
// goal measures. The staff step, the delay and the view change how the keys are typed and the
// path is seen, not the task.
inline constexpr std::array<std::string_view, 9> task_option_names{
    "--tension", "--continuity", "--bias", "--accel", "--slopes", "--samples", "--spacing", "--surface", "--inbetweens"};

// Each option of the script's OPTIONS line that the command line did not give, taken into
// `options` as if given there (the command line's own value wins over the script's). An option
// that is not one of carried_option_names (or --view), or a value out of its range, is
// "FILE:LINE: OPTIONS: ...; expected ..." with `options` unchanged.
[[nodiscard]] Expected<void> take_script_options(const ScriptOptions& line, const std::string& file_name,
                                                 CommonOptions& options);

// The words of the OPTIONS line --record writes: each option of `options.given.carried` with the
// value the session ran with ("--step 0.1 --spacing exact"), numbers with a '.' in every locale;
// empty when none was given.
std::string carried_options_words(const CommonOptions& options);

// The first task option (task_option_names) whose value in `options` differs from the exercise's
// (`task`), as the command line would give it ("--tension 0.5"); none when both set one task.
std::optional<std::string> changed_task_option(const CommonOptions& task, const CommonOptions& options);

} // namespace apcs
