#include "option_sets.h"

#include "apcs/animation/input_limits.h"
#include "apcs/animation/speed_law.h"
#include "apcs/formats/number_text.h"
#include "apcs/formats/text_fields.h"

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>

namespace apcs {

namespace {

// A number in `range`, read as the .dat reader reads one. The value goes on to CLI11 in its
// shortest form, so the two readers cannot disagree (an underflow, say). The validator has no
// description: --help shows the option's own name for the value and its range in the text.
CLI::Validator number_in(const limits::Range& range)
{
    return CLI::Validator(
        [range](std::string& text) -> std::string {
            const std::optional<double> value = parse_number(text);
            if (!value || !std::isfinite(*value))
                return "expected a number in " + range_text(range) + ", found " + quote_field(text);
            if (!range.contains(*value))
                return "expected a number in " + range_text(range) + ", found " + text;
            text = shortest_number(*value);
            return {};
        },
        "");
}

// "[1, 100000]": a range of whole numbers as a user types them.
std::string whole_range_text(const limits::Range& range)
{
    return "[" + std::to_string(static_cast<long long>(range.min)) + ", " +
           std::to_string(static_cast<long long>(range.max)) + "]";
}

// A whole number in `range`.
CLI::Validator whole_number_in(const limits::Range& range)
{
    return CLI::Validator(
        [range](std::string& text) -> std::string {
            const std::optional<std::size_t> value = parse_count_value(text);
            if (!value)
                return "expected a whole number in " + whole_range_text(range) + ", found " + quote_field(text);
            if (!range.contains(static_cast<double>(*value)))
                return "expected a whole number in " + whole_range_text(range) + ", found " + text;
            text = std::to_string(*value);
            return {};
        },
        "");
}

// One of `names`, exactly.
CLI::Validator one_of(std::vector<std::string> names)
{
    return CLI::Validator(
        [names](std::string& text) -> std::string {
            std::string listed;
            for (const std::string& name : names) {
                if (text == name)
                    return {};
                listed += (listed.empty() ? "" : ", ") + name;
            }
            return "expected one of " + listed + ", found " + quote_field(text);
        },
        "");
}

std::string alternatives(const std::vector<std::string>& names)
{
    std::string joined;
    for (const std::string& name : names)
        joined += (joined.empty() ? "" : "|") + name;
    return joined;
}

// A picture's name ends in its format's extension (any case) or has none: PNG bytes in x.svg
// would mislead.
// `a_file` is "a PNG file", say; `wanted` its extension (".png"), `also` another one or none.
// A file or folder named by an empty word ('') names nothing: refused before anything is read or
// made (it said ": cannot be made", or "internal error" for --record '').
const CLI::Validator a_name(
    [](std::string& text) -> std::string { return text.empty() ? "an empty name; expected a file or folder's name" : ""; },
    "");

CLI::Validator picture_name(const std::string& a_file, const std::string& wanted, const std::string& also = {})
{
    return CLI::Validator(
        [a_file, wanted, also](std::string& text) -> std::string {
            if (text.empty())
                return a_name(text);
            const std::string extension = std::filesystem::path(text).extension().string();
            if (extension.empty() || equals_ignoring_case(extension, wanted) ||
                (!also.empty() && equals_ignoring_case(extension, also)))
                return {};
            return a_file + "'s name ends in " + wanted + (also.empty() ? "" : " or " + also) + ", found '" + text +
                   "'";
        },
        "");
}

const CLI::Validator png_name = picture_name("a PNG file", ".png");
const CLI::Validator svg_name = picture_name("an SVG file", ".svg");
const CLI::Validator gif_name = picture_name("a GIF file", ".gif");
const CLI::Validator sixel_name = picture_name("a sixel file", ".six", ".sixel");
const CLI::Validator kitty_name = picture_name("a kitty picture", ".kitty");

} // namespace

// Help shows an option's value by its name only ("--tension T"): CLI11's types, validators and
// exclusions are said in the option's text where they matter.
std::string PlainOptionFormatter::make_option_opts(const CLI::Option* option) const
{
    return option->get_type_name().empty() ? std::string() : " " + option->get_type_name();
}

namespace {

void add_staff(CLI::App& command, CommonOptions& options)
{
    const std::string range = " in " + range_text(limits::staff_value) + ", default 0";
    const CLI::Validator staff = number_in(limits::staff_value);
    command.add_option("--tension", options.staff.tension, "tension" + range)->check(staff)->type_name("T");
    command.add_option("--continuity", options.staff.continuity, "continuity" + range)->check(staff)->type_name("C");
    command.add_option("--bias", options.staff.bias, "bias" + range)->check(staff)->type_name("B");
    command.add_option("--accel", options.staff.acceleration, "acceleration" + range)->check(staff)->type_name("A");
}

void add_curve(CLI::App& command, CommonOptions& options, std::vector<double>& slopes,
               const std::string& spacing_help = "in-betweens at the sample nearest each distance (the thesis, default) "
                                                 "or exactly on it")
{
    command
        .add_option("--slopes", slopes,
                    "end slopes DS[0] and DD[N], each in " + range_text(limits::end_slope) + ", default 1 1")
        ->expected(2)
        ->check(number_in(limits::end_slope))
        ->type_name("S0 S1");
    command
        .add_option("--samples", options.path.samples_per_segment,
                    "curve samples per segment, " + whole_range_text(limits::samples_per_segment) + ", default 32")
        ->check(whole_number_in(limits::samples_per_segment))
        ->type_name("N");
    const std::vector<std::string> spacings{"nearest", "exact"};
    command
        .add_option_function<std::string>(
            "--spacing",
            [&options](const std::string& name) {
                options.path.spacing = name == "exact" ? Spacing::exact : Spacing::nearest;
            },
            spacing_help)
        ->check(one_of(spacings))
        ->type_name(alternatives(spacings));
}

// SPEC §5.3: the blend (default) or the thesis' own Ferguson surface (§5.3.1).
void add_surface(CLI::App& command, CommonOptions& options)
{
    const std::vector<std::string> surfaces{"blend", "ferguson"};
    command
        .add_option_function<std::string>(
            "--surface",
            [&options](const std::string& name) {
                options.surface = name == "ferguson" ? SurfaceConstruction::ferguson : SurfaceConstruction::blend;
            },
            "surface fitting: a blend keeping both edge paths' whole shape (default), or the thesis' Ferguson "
            "surface from their end tangents (fig. 3.2.1)")
        ->check(one_of(surfaces))
        ->type_name(alternatives(surfaces));
}

void add_inbetween_count(CLI::App& command, CommonOptions& options)
{
    command
        .add_option("--inbetweens", options.path.inbetween_count,
                    "in-between frames M, " + whole_range_text(limits::inbetween_count) + ", default 12")
        ->check(whole_number_in(limits::inbetween_count))
        ->type_name("M");
}

// `flat_from_top`: the command sees data whose z are all 0 from the top unless a view is given
// (export, SPEC §7.5), which --view's help then says.
void add_view(CLI::App& command, CommonOptions& options, bool flat_from_top = false)
{
    const CLI::Validator degrees = number_in(limits::view_degrees);
    CLI::Option* theta =
        command.add_option("--theta", options.view.theta_degrees, "viewer direction theta in degrees, default 30")
            ->check(degrees)
            ->type_name("DEG");
    CLI::Option* phi =
        command.add_option("--phi", options.view.phi_degrees, "viewer direction phi in degrees, default 40")
            ->check(degrees)
            ->type_name("DEG");
    std::vector<std::string> names;
    std::string help = "a view along the axes instead of --theta and --phi";
    for (const ViewPreset& preset : view_presets) {
        names.emplace_back(preset.name);
        help += std::string(names.size() == 1 ? ": " : "; ") + preset.name + " " + preset.shows;
    }
    if (flat_from_top)
        help += ". Without --view, --theta or --phi, data whose z are all 0 is seen from the top";
    command
        .add_option_function<std::string>(
            "--view",
            [&options](const std::string& name) {
                for (const ViewPreset& preset : view_presets)
                    if (name == preset.name)
                        options.view = preset.angles;
            },
            help)
        ->check(one_of(names))
        ->type_name(alternatives(names))
        ->excludes(theta)
        ->excludes(phi);
}

void add_pictures(CLI::App& command, CommonOptions& options, const std::string& what)
{
    command.add_option("--png", options.png, "write " + what + " as a PNG as the monitor showed it (720x522)")
        ->check(png_name)
        ->type_name("FILE");
    command.add_option("--png-raw", options.png_raw, "write " + what + " as the bare 720x348 raster (pixel aspect 3:2)")
        ->check(png_name)
        ->type_name("FILE");
    command.add_option("--svg", options.svg, "write " + what + " as vector lines (SVG, 720x522)")
        ->check(svg_name)
        ->type_name("FILE");
}

// The picture of --png as the escape sequences that draw it on a terminal (SPEC §7.2.1); the batch
// commands only: the session's own pictures are --pixels' business.
void add_terminal_pictures(CLI::App& command, CommonOptions& options, const std::string& what)
{
    command.add_option("--sixel", options.sixel,
                       "write " + what + " as --png does, as sixel escape sequences (xterm -ti vt340, foot, WezTerm, "
                       "mlterm, mintty show it; tmux and screen do not pass it)")
        ->check(sixel_name)
        ->type_name("FILE");
    command.add_option("--kitty", options.kitty,
                       "write " + what + " as --png does, in the kitty graphics protocol (kitty, WezTerm, Ghostty, "
                       "Konsole show it; tmux and screen do not pass it)")
        ->check(kitty_name)
        ->type_name("FILE");
}

void add_delay(CLI::App& command, CommonOptions& options)
{
    command.add_option("--delay", options.delay_ms, "milliseconds per animation frame, default 200")
        ->check(whole_number_in(limits::delay_ms))
        ->type_name("MS");
}

// The frames as the session's animation shows them, one after the other.
void add_animation(CLI::App& command, CommonOptions& options)
{
    command.add_option("--gif", options.gif, "write the frames as an animated GIF (720x522, --delay each, looping)")
        ->check(gif_name)
        ->type_name("FILE");
    add_delay(command, options);
}

void add_print(CLI::App& command, CommonOptions& options)
{
    command.add_flag("--print", options.print, "write the numbers to standard output");
}

void add_out(CLI::App& command, CommonOptions& options, const std::string& what)
{
    command.add_option("--out", options.out, "folder " + what + " go to, default the current one")
        ->check(a_name)
        ->type_name("DIR");
}

void add_glyphs(CLI::App& command, CommonOptions& options)
{
    const std::vector<std::string> glyphs{"ascii", "braille", "blocks"};
    command.add_option_function<std::string>(
           "--glyphs",
           [&options](const std::string& name) {
               options.glyphs = name == "ascii" ? GlyphSet::ascii : name == "braille" ? GlyphSet::braille : GlyphSet::blocks;
           },
           "characters that draw the raster; default braille in a UTF-8 locale on a terminal that shows it, "
           "else ascii")
        ->check(one_of(glyphs))
        ->type_name(alternatives(glyphs));
}

void add_colour(CLI::App& command, CommonOptions& options)
{
    const std::vector<std::string> choices{"auto", "always", "never"};
    command.add_option_function<std::string>(
           "--color",
           [&options](const std::string& name) {
               options.colour = name == "always" ? ColourChoice::always
                                : name == "never" ? ColourChoice::never
                                                  : ColourChoice::automatic;
           },
           "the path screen's overlays (ghost, tangents, law, region, key frames, in-betweens) each in its own "
           "colour; default auto: where the terminal has 8 colours and NO_COLOR is unset or empty")
        ->check(one_of(choices))
        ->type_name(alternatives(choices));
}

void add_pixels(CLI::App& command, CommonOptions& options)
{
    const std::vector<std::string> choices{"auto", "sixel", "kitty", "off"};
    command.add_option_function<std::string>(
           "--pixels",
           [&options](const std::string& name) {
               options.pixels = name == "auto"    ? PixelChoice::automatic
                                : name == "sixel" ? PixelChoice::sixel
                                : name == "kitty" ? PixelChoice::kitty
                                                  : PixelChoice::off;
           },
           "the drawing area as real pixels: sixel (xterm -ti vt340, foot, WezTerm, mlterm), kitty "
           "(kitty, WezTerm, Ghostty, Konsole), or auto: as the terminal answers, never inside tmux or screen; "
           "default off")
        ->check(one_of(choices))
        ->type_name(alternatives(choices));
}

} // namespace

void add_carried_options(CLI::App& app, CommonOptions& options, std::vector<double>& slopes)
{
    add_staff(app, options);
    add_curve(app, options, slopes);
    add_surface(app, options);
    add_inbetween_count(app, options);
    add_view(app, options);
    add_delay(app, options);
    app.add_option("--step", options.step,
                   "staff step per key, " + range_text(limits::staff_step) + ", default 0.05")
        ->check(number_in(limits::staff_step))
        ->type_name("S");
}

void add_session_options(CLI::App& app, CommonOptions& options, std::vector<double>& slopes)
{
    add_carried_options(app, options, slopes);
    add_glyphs(app, options);
    add_colour(app, options);
    add_pixels(app, options);
    add_pictures(app, options, "the overlay of all frames");
    app.add_option("--workdir", options.workdir, "folder the session reads and writes, default the current one")
        ->check(a_name)
        ->type_name("DIR");
    app.add_option("--keys", options.keys, "replay the keystrokes of FILE")->check(a_name)->type_name("FILE");
    app.add_option("--record", options.record, "record the keystrokes to FILE")->check(a_name)->type_name("FILE");
    app.add_option("--handout", options.handout,
                   "write each ;; caption's screen of the --keys replay, once its keys have played, to DIR as "
                   "NN-STEP.png and NN-STEP.txt, and DIR/index.html to print them from a browser")
        ->check(a_name)
        ->type_name("DIR");
    app.add_flag("--paper", options.paper, "draw the --handout pictures black on white, for printing");
    app.add_option_function<std::string>(
           "--pace",
           [&options](const std::string& text) {
               options.pace = text == "step" ? ReplayPace{ReplayPace::Kind::on_space, 0}
                                             : ReplayPace{ReplayPace::Kind::every, std::stoi(text)};
           },
           "play the --keys script one step (a key, or a typed line) every MS milliseconds, " +
               whole_range_text(limits::pace_ms) + ", or one step per Space ('step'), with its ;; captions; PgDn (or ]) plays on to the next caption, PgUp (or [) and Home go back")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                if (text == "step")
                    return {};
                const std::string expected = "expected milliseconds in " + whole_range_text(limits::pace_ms) +
                                             " or 'step', found ";
                const std::optional<std::size_t> value = parse_count_value(text);
                if (!value)
                    return expected + quote_field(text);
                if (!limits::pace_ms.contains(static_cast<double>(*value)))
                    return expected + text;
                text = std::to_string(*value);
                return {};
            },
            ""))
        ->type_name("MS|step");
}

void add_path_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes)
{
    add_staff(command, options);
    add_curve(command, options, slopes);
    add_inbetween_count(command, options);
    add_view(command, options);
    add_pictures(command, options, "the path's screen");
    add_terminal_pictures(command, options, "the path's screen");
    add_print(command, options);
}

void add_fit_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes)
{
    add_staff(command, options);
    add_curve(command, options, slopes);
    add_surface(command, options);
    add_inbetween_count(command, options);
    add_view(command, options);
    add_pictures(command, options, "all frames overlaid");
    add_terminal_pictures(command, options, "all frames overlaid");
    add_animation(command, options);
    add_print(command, options);
    add_out(command, options, "the in-between files");
}

void add_export_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes,
                                ExportRequest& request)
{
    command.add_option("--sif", request.sif, "the Synfig document to write (.sif); - for standard output")
        ->required()
        ->check(a_name)
        ->type_name("OUT.sif");
    const std::vector<std::string> motions{"tcb", "frames"};
    command
        .add_option_function<std::string>(
            "--sif-motion",
            [&request](const std::string& name) { request.motion = name == "frames" ? SifMotion::frames : SifMotion::tcb; },
            "one path: the circle moves through TCB waypoints at the control points (default), or through "
            "APCS's own frames, one linear waypoint a frame (acceleration and end slopes kept)")
        ->check(one_of(motions))
        ->type_name(alternatives(motions));
    command
        .add_option("--frames-per-span", request.timing.frames_per_span,
                    "one path, tcb: Synfig frames from a control point's waypoint to the next, " +
                        whole_range_text(limits::sif_frames_per_span) + ", default 12")
        ->check(whole_number_in(limits::sif_frames_per_span))
        ->type_name("K");
    command
        .add_option("--fps", request.timing.fps,
                    "the document's frames per second, " + range_text(limits::sif_fps) + ", default 24")
        ->check(number_in(limits::sif_fps))
        ->type_name("F");
    add_staff(command, options);
    add_curve(command, options, slopes);
    add_surface(command, options);
    add_inbetween_count(command, options);
    add_view(command, options, true);
}

void add_inbetween_command_options(CLI::App& command, CommonOptions& options, InbetweenSettings& settings)
{
    add_inbetween_count(command, options);
    command
        .add_option("--frames", settings.frame_intervals,
                    "T: frames 0 to T, " + whole_range_text(limits::frame_intervals) + ", default M + 1")
        ->check(whole_number_in(limits::frame_intervals))
        ->type_name("T");
    const std::vector<std::string> laws{"linear", "sqrt", "square", "ease-in", "ease-out", "ease-in-out"};
    command
        .add_option_function<std::string>(
            "--law", [&settings](const std::string& name) { settings.law = *speed_law_from_name(name); },
            "the interpolation law, default linear")
        ->check(one_of(laws))
        ->type_name(alternatives(laws));
    const std::vector<std::string> paddings{"apcs", "start", "end", "middle", "midpoint"};
    command
        .add_option_function<std::string>(
            "--pad", [&settings](const std::string& name) { settings.padding = *padding_from_name(name); },
            "how the key with fewer points is padded, default apcs")
        ->check(one_of(paddings))
        ->type_name(alternatives(paddings));
    add_view(command, options);
    add_pictures(command, options, "all frames overlaid");
    add_terminal_pictures(command, options, "all frames overlaid");
    add_animation(command, options);
    add_print(command, options);
    add_out(command, options, "the in-between files");
}

void add_draw_command_options(CLI::App& command, CommonOptions& options)
{
    add_view(command, options);
    add_pictures(command, options, "the drawing");
    add_terminal_pictures(command, options, "the drawing");
}

void add_play_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes, bool& tree)
{
    add_staff(command, options);
    add_curve(command, options, slopes, "frames at the sample nearest each distance (the thesis) or exactly on "
                                        "it; overrides the scene's SPACING line, default exact");
    add_surface(command, options);
    add_view(command, options);
    add_glyphs(command, options);
    add_pixels(command, options);
    add_pictures(command, options, "all frames overlaid");
    add_terminal_pictures(command, options, "all frames overlaid");
    add_animation(command, options);
    add_print(command, options);
    command.add_option("--out", options.out, "folder to write the frames to as frm000.dat ...")
        ->check(a_name)
        ->type_name("DIR");
    command.add_flag("--tree", tree, "print the scene's data-structure tree (thesis fig. 3.3.2) and stop");
}

void add_figures_command_options(CLI::App& command, CommonOptions& options, std::vector<double>& slopes)
{
    add_staff(command, options);
    add_curve(command, options, slopes);
    add_inbetween_count(command, options);
    command.add_option("--workdir", options.workdir, "folder of the examples, default the installed ones")
        ->check(a_name)
        ->type_name("DIR");
    add_out(command, options, "the pictures");
    command.add_flag("--paper", options.paper,
                     "draw the pictures black on white, for printing or a projector in a bright room");
}

} // namespace apcs
