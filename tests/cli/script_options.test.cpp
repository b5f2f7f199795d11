#include "apcs/cli/script_options.h"

#include <catch2/catch.hpp>

#include <string>

using namespace apcs;

namespace {

CommonOptions taken(const std::string& words, CommonOptions options = {})
{
    const Expected<void> result = take_script_options({words, 3}, "mine.keys", options);
    INFO(words);
    REQUIRE(result);
    return options;
}

} // namespace

TEST_CASE("a script's OPTIONS set what the command line left unset, as given there", "[cli][record][options]")
{
    const CommonOptions options =
        taken("--step 0.1 --inbetweens 20 --spacing exact --surface ferguson --slopes 0 0.5 --tension=-0.5 "
              "--samples 8 --delay 40 --continuity 0.25 --bias -1 --accel 0.75");
    CHECK(options.step == 0.1);
    CHECK(options.path.inbetween_count == 20);
    CHECK(options.path.spacing == Spacing::exact);
    CHECK(options.surface == SurfaceConstruction::ferguson);
    CHECK(options.path.slopes.start == 0.0);
    CHECK(options.path.slopes.end == 0.5);
    CHECK(options.staff.tension == -0.5);
    CHECK(options.staff.continuity == 0.25);
    CHECK(options.staff.bias == -1.0);
    CHECK(options.staff.acceleration == 0.75);
    CHECK(options.path.samples_per_segment == 8);
    CHECK(options.delay_ms == 40);
    CHECK(options.given.slopes);
    CHECK(options.given.spacing);
    CHECK(options.given.delay);
    CHECK_FALSE(options.given.theta);
    // Written back for the next recording in carried_option_names' order, numbers shortest.
    CHECK(carried_options_words(options) == "--tension -0.5 --continuity 0.25 --bias -1 --accel 0.75 --slopes 0 0.5 "
                                            "--samples 8 --spacing exact --surface ferguson --inbetweens 20 "
                                            "--delay 40 --step 0.1");
    CHECK(carried_options_words(taken(carried_options_words(options))) == carried_options_words(options));
}

TEST_CASE("a view preset in a script's OPTIONS is its theta and phi", "[cli][record][options]")
{
    const CommonOptions options = taken("--view side");
    CHECK(options.given.theta);
    CHECK(options.given.phi);
    CHECK(carried_options_words(options) == "--theta -90 --phi 90");
    CHECK(carried_options_words(CommonOptions{}).empty());
}

TEST_CASE("an option the command line gave wins over the script's", "[cli][record][options]")
{
    CommonOptions command_line;
    command_line.step = 0.05;
    command_line.given.carried = {"--step"};
    const CommonOptions options = taken("--step 0.1 --inbetweens 20", command_line);
    CHECK(options.step == 0.05);
    CHECK(options.path.inbetween_count == 20);
    CHECK(carried_options_words(options) == "--inbetweens 20 --step 0.05");
}

TEST_CASE("a script's OPTIONS that name another option or a value out of range are refused with FILE:LINE",
          "[cli][record][options]")
{
    const std::string list = "; expected the session's options --tension, --continuity, --bias, --accel, --slopes, "
                             "--samples, --spacing, --surface, --inbetweens, --theta, --phi, --delay, --step or "
                             "--view, each with its value, as on the command line";
    const auto [words, message] = GENERATE_COPY(table<std::string, std::string>({
        {"--png /tmp/x.png", "mine.keys:3: OPTIONS --png: not an option a script carries" + list},
        {"--step 0.1 --workdir /", "mine.keys:3: OPTIONS --workdir: not an option a script carries" + list},
        {"--record=/tmp/x.keys", "mine.keys:3: OPTIONS --record: not an option a script carries" + list},
        {"--glyphs ascii", "mine.keys:3: OPTIONS --glyphs: not an option a script carries" + list},
        {"-h", "mine.keys:3: OPTIONS -h: not an option a script carries" + list},
        {"--step 5", "mine.keys:3: OPTIONS: --step: expected a number in [0.001, 2], found 5"},
        {"--step 0,1", "mine.keys:3: OPTIONS: --step: expected a number in [0.001, 2], found '0,1'"},
        {"--spacing far", "mine.keys:3: OPTIONS: --spacing: expected one of nearest, exact, found 'far'"},
        {"extra", "mine.keys:3: OPTIONS: extra: neither an option nor its value" + list},
        {"--step 0.1 stray words", "mine.keys:3: OPTIONS: stray: neither an option nor its value" + list},
        {"--step 0.1 --step=0.2", "mine.keys:3: OPTIONS --step given twice; expected each option once"},
        {"--st\xFF""ep 1", "mine.keys:3: OPTIONS '--st\\xFFep': not an option a script carries" + list},
        {"--slopes 1",
         "mine.keys:3: OPTIONS: --slopes: At least 2 required but received 1; expected each option with its value, "
         "as on the command line"},
    }));
    CommonOptions options;
    const Expected<void> refused = take_script_options({words, 3}, "mine.keys", options);
    REQUIRE_FALSE(refused);
    CHECK(refused.error().to_string() == message);
    CHECK(options.step == 0.05);
    CHECK(options.given.carried.empty());
}

TEST_CASE("a task option is one that starts the staff elsewhere or changes what a goal measures",
          "[cli][record][options]")
{
    const CommonOptions defaults;
    CHECK_FALSE(changed_task_option(defaults, defaults));
    CHECK_FALSE(changed_task_option(defaults, taken("--step 0.1 --delay 40 --view top")));
    CHECK(changed_task_option(defaults, taken("--step 0.1 --tension 0.5")) == "--tension 0.5");
    CHECK(changed_task_option(defaults, taken("--slopes 0 1")) == "--slopes 0 1");
    CHECK(changed_task_option(defaults, taken("--inbetweens 6")) == "--inbetweens 6");
    CHECK(changed_task_option(defaults, taken("--spacing exact")) == "--spacing exact");
    CHECK(changed_task_option(taken("--inbetweens 6"), taken("--inbetweens 6 --step 0.2")) == std::nullopt);
    // The defaults given out loud set the same task.
    CHECK_FALSE(changed_task_option(defaults, taken("--inbetweens 12 --samples 32 --slopes 1 1 --tension 0")));
}
