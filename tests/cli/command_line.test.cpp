#include "apcs/cli/command_line.h"
#include "apcs/version.h"

#include "support/run_apcs.h"
#include "support/temp_folder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace apcs;

using test::run_apcs;

TEST_CASE("the --version option names the program, its version and the thesis, and exits 0", "[cli]")
{
    const auto result = run_apcs({"--version"});
    REQUIRE(result.status == 0);
    REQUIRE(result.out.starts_with("apcs (APCS) " + std::string(version) + "\n"));
    REQUIRE(result.out.find("1989 master's thesis \"Design of An Animation Path\nControl System\"") != std::string::npos);
}

TEST_CASE("the --help option lists the commands and exits 0", "[cli]")
{
    const auto result = run_apcs({"--help"});
    REQUIRE(result.status == 0);
    for (const char* command : {"path", "inbetween", "fit", "figures"})
        REQUIRE(result.out.find(command) != std::string::npos);
    CHECK(result.out.find("manual.txt") != std::string::npos);
}

TEST_CASE("bad usage is exit 2 with one line of reason and where help is", "[cli]")
{
    for (const auto& arguments : std::vector<std::vector<std::string>>{
             {"--frobnicate"},
             {"path", "a.dat", "--tension", "2"},
             {"path", "a.dat", "--tension", "nan"},
             {"path", "a.dat", "--slopes", "0.5"},
             {"path", "a.dat", "--slopes", "0.5", "1.5"},
             {"path", "a.dat", "--samples", "0"},
             {"path", "a.dat", "--spacing", "wobbly"},
             {"path", "a.dat", "--glyphs", "emoji"},
             {"path"},
             {"fit", "a.dat"},
             {"dance", "robot.scn"},
             {"play", "robot.scn", "--delay", "-1"},
             {"play"},
         }) {
        const auto result = run_apcs(arguments);
        CAPTURE(arguments);
        REQUIRE(result.status == 2);
        REQUIRE(result.out.empty());
        REQUIRE(result.err.starts_with("apcs: "));
        const std::string command = arguments.front().starts_with("-") || arguments.front() == "dance"
                                        ? "apcs"
                                        : "apcs " + arguments.front();
        const std::string try_help = "Try '" + command + " --help' for more information.\n";
        REQUIRE(result.err.ends_with(try_help));
        REQUIRE(std::count(result.err.begin(), result.err.end(), '\n') == 2);
    }
}

TEST_CASE("a usage error says what was expected", "[cli]")
{
    struct Row {
        std::vector<std::string> arguments;
        std::string line;
    };
    const Row rows[] = {
        {{"path", "a.dat", "--tension", "2"}, "apcs: --tension: expected a number in [-1, 1], found 2"},
        {{"path", "a.dat", "--tension", "nan"}, "apcs: --tension: expected a number in [-1, 1], found 'nan'"},
        {{"path", "a.dat", "--samples", "0"}, "apcs: --samples: expected a whole number in [1, 100000], found 0"},
        {{"path", "a.dat", "--spacing", "wobbly"}, "apcs: --spacing: expected one of nearest, exact, found 'wobbly'"},
        {{"--frobnicate"}, "apcs: unknown option --frobnicate"},
        {{"dance", "robot.scn"}, "apcs: unknown command 'dance' (the commands: path, inbetween, fit, export, draw, play, figures, grade)"},
        {{"play", "robot.scn", "--inbetweens", "3"}, "apcs: --inbetweens is not an option of 'apcs play' (it is one of 'apcs', 'apcs path', 'apcs inbetween', 'apcs fit', 'apcs export', 'apcs figures')"},
        {{"fit", "a", "b", "c", "d", "--keys", "x.keys"}, "apcs: --keys is not an option of 'apcs fit' (it is one of 'apcs')"},
        {{"--glyphs", "ascii", "path", "a.dat"}, "apcs: --glyphs is not an option of 'apcs path' (it is one of 'apcs', 'apcs play')"},
        {{"--out", "x", "path", "a.dat"},
         "apcs: --out is not an option of 'apcs path' (it is one of 'apcs inbetween', 'apcs fit', 'apcs play', "
         "'apcs figures')"},
        {{"--print", "path", "a.dat"}, "apcs: --print goes after the command: apcs path ... --print"},
        {{"--png", "a.png", "path", "a.dat", "--png", "b.png"}, "apcs: --png is given twice, before and after 'path'"},
        {{"draw", "a.dat", "--png", "x.png", "--png-raw", "x.png"},
         "apcs: --png-raw names a file another picture option names: x.png"},
        {{"fit", "a.dat", "b.dat"}, "apcs: fit takes four files KEY1 KEY2 PATH_FIRST PATH_LAST; 2 given"},
        {{"fit", "a", "b", "c", "d", "e", "--print"}, "apcs: fit takes four files KEY1 KEY2 PATH_FIRST PATH_LAST; 5 given"},
        {{"fit", "--print"}, "apcs: fit takes four files KEY1 KEY2 PATH_FIRST PATH_LAST; 0 given"},
        // Issue 45: a wrong count of --slopes values had been told as the files' count.
        {{"fit", "a", "b", "c", "d", "--slopes", "0.5"}, "apcs: --slopes takes 2 values (S0 S1); 1 given"},
        {{"path", "a.dat", "--slopes", "0.5"}, "apcs: --slopes takes 2 values (S0 S1); 1 given"},
        {{"--slopes", "0.5"}, "apcs: --slopes takes 2 values (S0 S1); 1 given"},
        {{"path", "a.dat", "--tension"}, "apcs: --tension takes 1 value (T); 0 given"},
        {{"inbetween", "a.dat"}, "apcs: inbetween takes two key files KEY1 KEY2; 1 given"},
        {{"path", "a.dat", "b.dat"}, "apcs: path takes one path file FILE.dat (or FILE.sif); 2 given"},
        {{"play"}, "apcs: play takes one scene file SCENE.scn; 0 given"},
        {{"draw", "--png", "x.png"}, "apcs: draw takes one or more .dat files; 0 given"},
        {{"figures", "data"}, "apcs: figures takes no files (--out names the folder); 1 given"},
    };
    for (const Row& row : rows) {
        CAPTURE(row.arguments);
        const auto result = run_apcs(row.arguments);
        CHECK(result.status == 2);
        CHECK(result.err.substr(0, result.err.find('\n')) == row.line);
    }
}

TEST_CASE("the default glyphs are braille only in a UTF-8 locale on a terminal that shows it (SPEC 7.2)", "[cli]")
{
    struct Row {
        const char* codeset;
        const char* term;
        GlyphSet expected;
    };
    const Row rows[] = {
        {"UTF-8", "xterm-256color", GlyphSet::braille},
        {"UTF-8", "xterm", GlyphSet::braille},
        {"UTF-8", "screen", GlyphSet::braille},
        {"UTF-8", "tmux-256color", GlyphSet::braille},
        {"UTF-8", "vte-256color", GlyphSet::braille}, // GNOME's VTE: not a DEC terminal
        {"utf8", "xterm", GlyphSet::braille},
        {"UTF8", "rxvt-unicode", GlyphSet::braille},
        {"UTF-8", "linux", GlyphSet::ascii}, // the Linux console has no braille
        {"UTF-8", "linux-16color", GlyphSet::ascii},
        {"UTF-8", "vt100", GlyphSet::ascii},
        {"UTF-8", "vt220", GlyphSet::ascii},
        {"UTF-8", "vt52", GlyphSet::ascii},
        {"UTF-8", "dumb", GlyphSet::ascii},
        {"UTF-8", "", GlyphSet::ascii},
        {"ANSI_X3.4-1968", "xterm", GlyphSet::ascii}, // LANG=C
        {"ISO-8859-1", "xterm", GlyphSet::ascii},
        {"", "xterm", GlyphSet::ascii},
        {"UTF-16", "xterm", GlyphSet::ascii},
    };
    for (const Row& row : rows) {
        INFO("codeset '" << row.codeset << "', TERM '" << row.term << "'");
        CHECK(default_glyphs(row.codeset, row.term) == row.expected);
        const Expected<GlyphSet> chosen = terminal_glyphs(GlyphSet::automatic, row.codeset, row.term);
        REQUIRE(chosen);
        CHECK(*chosen == row.expected);
    }
}

TEST_CASE("a glyph set asked for is shown where the locale can, else refused with one line", "[cli]")
{
    struct Row {
        GlyphSet asked;
        const char* codeset;
        const char* term;
        std::optional<GlyphSet> expected; // nullopt: refused
    };
    const Row rows[] = {
        {GlyphSet::ascii, "ANSI_X3.4-1968", "xterm", GlyphSet::ascii},
        {GlyphSet::ascii, "UTF-8", "xterm", GlyphSet::ascii},
        {GlyphSet::braille, "UTF-8", "xterm", GlyphSet::braille},
        {GlyphSet::blocks, "UTF-8", "xterm", GlyphSet::blocks},
        {GlyphSet::braille, "UTF-8", "linux", GlyphSet::braille}, // asked for: the user knows the font
        {GlyphSet::braille, "ANSI_X3.4-1968", "xterm", std::nullopt},
        {GlyphSet::blocks, "ANSI_X3.4-1968", "xterm", std::nullopt},
        {GlyphSet::braille, "ISO-8859-1", "xterm", std::nullopt},
    };
    for (const Row& row : rows) {
        INFO("codeset '" << row.codeset << "', TERM '" << row.term << "'");
        const Expected<GlyphSet> chosen = terminal_glyphs(row.asked, row.codeset, row.term);
        REQUIRE(chosen.has_value() == row.expected.has_value());
        if (chosen)
            CHECK(*chosen == *row.expected);
    }
    const Expected<GlyphSet> braille = terminal_glyphs(GlyphSet::braille, "ANSI_X3.4-1968", "xterm");
    REQUIRE_FALSE(braille);
    CHECK(braille.error().to_string() ==
          "apcs: --glyphs braille needs a UTF-8 locale (LANG=C.UTF-8 or similar); use --glyphs ascii");
    const Expected<GlyphSet> blocks = terminal_glyphs(GlyphSet::blocks, "ANSI_X3.4-1968", "xterm");
    REQUIRE_FALSE(blocks);
    CHECK(blocks.error().to_string() ==
          "apcs: --glyphs blocks needs a UTF-8 locale (LANG=C.UTF-8 or similar); use --glyphs ascii");
    // A UTF-8 locale named but not installed: setlocale fell back to "C", and the name is why.
    const Expected<GlyphSet> missing = terminal_glyphs(GlyphSet::braille, "ANSI_X3.4-1968", "xterm", "de_DE.UTF-8");
    REQUIRE_FALSE(missing);
    CHECK(missing.error().to_string() ==
          "apcs: --glyphs braille needs a UTF-8 locale: de_DE.UTF-8 is not installed here (locale -a lists those "
          "that are); use LANG=C.UTF-8, or --glyphs ascii");
    CHECK(terminal_glyphs(GlyphSet::braille, "ANSI_X3.4-1968", "xterm", "C").error().to_string() ==
          "apcs: --glyphs braille needs a UTF-8 locale (LANG=C.UTF-8 or similar); use --glyphs ascii");
    CHECK(terminal_glyphs(GlyphSet::braille, "UTF-8", "xterm", "de_DE.utf8").value() == GlyphSet::braille);
}

TEST_CASE("the session takes the command line's answers only where they were given", "[cli]")
{
    const CommonOptions defaults;
    const SessionSettings plain = session_settings(defaults);
    CHECK_FALSE(plain.theta_degrees);
    CHECK_FALSE(plain.phi_degrees);
    CHECK_FALSE(plain.delay_ms);
    CHECK_FALSE(plain.slopes);
    CHECK_FALSE(plain.overlay_png);
    CHECK(plain.staff == StaffValues{});
    CHECK(plain.samples_per_segment == 32);
    CHECK(plain.inbetween_count == 12);
    CHECK(plain.step == 0.05);

    CommonOptions options;
    options.view = {10.0, 20.0};
    options.delay_ms = 50;
    options.path.slopes = {0.5, 0.25};
    options.path.samples_per_segment = 8;
    options.path.inbetween_count = 3;
    options.path.spacing = Spacing::exact;
    options.step = 0.1;
    options.staff = {0.1, -0.2, 0.3, -0.4};
    options.png = "overlay.png";
    // Values without the flags that say they were typed: the session keeps the thesis' example.
    const SessionSettings untyped = session_settings(options);
    CHECK_FALSE(untyped.theta_degrees);
    CHECK_FALSE(untyped.delay_ms);
    CHECK_FALSE(untyped.slopes);
    CHECK(untyped.staff == options.staff); // the staff seed always
    CHECK(untyped.overlay_png == "overlay.png");
    CHECK(untyped.samples_per_segment == 8);
    CHECK(untyped.inbetween_count == 3);
    CHECK(untyped.spacing == Spacing::exact);
    CHECK(untyped.step == 0.1);

    options.given = {true, true, true, true, true, {}};
    const SessionSettings typed = session_settings(options);
    CHECK(typed.theta_degrees == 10.0);
    CHECK(typed.phi_degrees == 20.0);
    CHECK(typed.delay_ms == 50);
    REQUIRE(typed.slopes);
    CHECK(typed.slopes->start == 0.5);
    CHECK(typed.slopes->end == 0.25);

    options.given = {false, true, false, false, false, {}};
    const SessionSettings phi_only = session_settings(options);
    CHECK_FALSE(phi_only.theta_degrees);
    CHECK(phi_only.phi_degrees == 20.0);

    // With --workdir, a relative --png is still named from where apcs was started.
    options.workdir = "elsewhere";
    const SessionSettings moved = session_settings(options);
    REQUIRE(moved.overlay_png);
    CHECK(*moved.overlay_png == (std::filesystem::current_path() / "overlay.png").string());
    options.png = "/tmp/overlay.png";
    CHECK(session_settings(options).overlay_png == "/tmp/overlay.png");
    options.svg = "overlay.svg";
    CHECK(session_settings(options).overlay_svg == (std::filesystem::current_path() / "overlay.svg").string());
}

TEST_CASE("Enter at the session's prompts takes --theta, --phi, --delay and --slopes where given", "[cli][session]")
{
    const test::TempFolder folder;
    for (const char* name : {"key1.dat", "key2.dat", "way1.dat"})
        std::filesystem::copy_file(std::filesystem::path(APCS_SOURCE_DIR) / "data" / "n-to-l" / name, folder / name);
    const auto script = folder.write("enter.keys", "ENTER\nENTER\nENTER\nTEXT way1.dat\nENTER\nENTER\n");
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string(), "--glyphs",
                                        "ascii", "--theta", "10", "--phi", "20", "--delay", "50", "--slopes", "0.5",
                                        "0.25"});
    REQUIRE(result.status == 0);
    const std::string log = test::read_all(folder / "apcs.log");
    INFO(log);
    CHECK(log.find("view: theta 10, phi 20, delay 50 ms") != std::string::npos);
    CHECK(log.find("slopes DS[0] 0.5, DD[N] 0.25") != std::string::npos);
}

TEST_CASE("the pace of a replay (--pace) takes milliseconds from 1 to 60000 or 'step', and needs --keys and a terminal", "[cli][pace]")
{
    for (const auto& [value, expected] :
         {std::pair{"0", "apcs: --pace: expected milliseconds in [1, 60000] or 'step', found 0"},
          std::pair{"fast", "apcs: --pace: expected milliseconds in [1, 60000] or 'step', found 'fast'"},
          std::pair{"60001", "apcs: --pace: expected milliseconds in [1, 60000] or 'step', found 60001"}}) {
        const auto result = test::run_apcs({"--pace", value});
        REQUIRE(result.status == 2);
        REQUIRE(result.err.starts_with(std::string(expected) + "\n"));
    }
    const auto no_keys = test::run_apcs({"--pace", "step"});
    REQUIRE(no_keys.status == 2);
    REQUIRE(no_keys.err == "apcs: --pace paces a --keys replay; give --keys FILE\n");
    const test::TempFolder folder;
    const auto script = folder.write("class.keys", ";; Step 1\nENTER\n");
    // The tests run without a terminal: the script would play at once, so --pace is refused.
    const auto headless = test::run_apcs({"--keys", script.string(), "--pace", "500", "--workdir", folder.path().string()});
    REQUIRE(headless.status == 2);
    REQUIRE(headless.err ==
            "apcs: --pace paces a replay on a terminal; without one the script plays at once (leave --pace out)\n");
    REQUIRE(test::run_apcs({"path", "x.dat", "--pace", "5"}).err.starts_with("apcs: --pace is not an option of 'apcs path'"));
}

TEST_CASE("a headless replay prints each step's final screen and the captions where it reaches them", "[cli][pace]")
{
    const test::TempFolder folder;
    folder.write("key1.dat", "0 0 0\n0 6 0\n");
    folder.write("key2.dat", "0 0 10\n0 6 10\n");
    const auto script = folder.write("class.keys", ";; Step 1: the key frames\nENTER\nENTER\n;; Step 2: the view\n"
                                                   "TEXT 0 90 100\nENTER\n");
    const auto result = test::run_apcs({"--keys", script.string(), "--workdir", folder.path().string(), "--glyphs", "ascii"});
    REQUIRE(result.status == 0);
    const std::string& out = result.out;
    const auto at = [&](const std::string& text) { return out.find(text); };
    REQUIRE(at(";; Step 1: the key frames\n") == 0);
    REQUIRE(at("--- step 1: KEY1 file\n") < at("--- step 1: KEY2 file\n"));
    REQUIRE(at("--- step 1: KEY2 file\n") < at(";; Step 2: the view\n"));
    // The view step's final screen shows its answer typed, before Enter took it.
    const std::size_t view = at("--- step 2: view and delay\n");
    REQUIRE(view != std::string::npos);
    REQUIRE(out.find("0 90 100_", view) != std::string::npos);
}

TEST_CASE("a flag given a value says it is a flag, not CLI11's Could not convert", "[cli]")
{
    const auto run = run_apcs({"--paper=banana", "--keys", "lesson.keys", "--handout", "h"});
    REQUIRE(run.status == 2);
    REQUIRE(run.err == "apcs: --paper is a flag and takes no value ('banana' given); write --paper alone\n"
                       "Try 'apcs --help' for more information.\n");
}

TEST_CASE("a file or folder named by an empty word is refused as a usage error, naming its option", "[cli]")
{
    const auto refused = [](std::vector<std::string> arguments) {
        const auto run = run_apcs(std::move(arguments));
        CAPTURE(run.err);
        REQUIRE(run.status == 2);
        return run.err.substr(0, run.err.find('\n'));
    };
    // They said ": cannot be made: No such file or directory" and, for --record, "internal error".
    REQUIRE(refused({"--keys", "lesson.keys", "--handout", ""}) == "apcs: --handout: an empty name; expected a file or folder's name");
    REQUIRE(refused({"--keys", "lesson.keys", "--record", ""}) == "apcs: --record: an empty name; expected a file or folder's name");
    REQUIRE(refused({"--keys", ""}) == "apcs: --keys: an empty name; expected a file or folder's name");
    REQUIRE(refused({"--workdir", ""}) == "apcs: --workdir: an empty name; expected a file or folder's name");
    REQUIRE(refused({"play", "car.scn", "--out", ""}) == "apcs: --out: an empty name; expected a file or folder's name");
    REQUIRE(refused({"path", "ani1.dat", "--png", ""}) == "apcs: --png: an empty name; expected a file or folder's name");
}

TEST_CASE("a ROLL whose turn is no number is named at its own line, not at the OBJECT line", "[cli][scene]")
{
    const test::TempFolder folder;
    folder.write("wheel.dat", "0 0 0\n0 0 1\n");
    folder.write("road.dat", "0 0 0\n0 10 0\n");
    folder.write("w.scn", "FRAMES 10\nOBJECT wheel\nSHAPE wheel.dat\nMOVE road.dat\nROLL 1e-308\n");
    const auto run = run_apcs({"play", (folder / "w.scn").string(), "--print"});
    REQUIRE(run.status == 1);
    // It said "w.scn:2: ... (its MOVE, ROTATE and SCALE composed with its parents')".
    REQUIRE(run.err == (folder / "w.scn").string() +
                           ":5: object wheel reaches values that are not numbers at frame 1: its ROLL turns it by its "
                           "hub's travel / RADIUS 1e-308 radians, beyond a number; expected a wheel's radius\n");
}
