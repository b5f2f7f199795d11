#pragma once

#include "apcs/base/diagnostic.h"
#include "apcs/cli/options.h"
#include "apcs/formats/key_script.h"

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

// The session's options that shape what its keys do, which a key script may carry on its OPTIONS
// line (key_script.h): with another staff step, in-between count or spacing the same keys reach
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

// Of carried_option_names, those `given_by_name` says were given; --view gives --theta and --phi.
std::vector<std::string> given_carried_options(const std::function<bool(const std::string& name)>& given_by_name);

// apcs's defaults with the script's OPTIONS line taken, its options named in given.carried: what
// the script alone sets (an exercise's task). The problems as take_script_options says them.
[[nodiscard]] Expected<CommonOptions> options_of_script(const ScriptOptions& line, const std::string& file_name);

// Each option the script gave (`script`, options_of_script's) that `options` was not given, taken
// into `options` as if given there.
void merge_script_options(const CommonOptions& script, CommonOptions& options);

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
