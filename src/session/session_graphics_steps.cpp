// Steps 3–6 after the text prompts (thesis Ch. 4.2): the path shaped in graphics mode and written
// back, surface fitting (s_fiting.c) and Showing_Animation.
#include "apcs/session/session_steps.h"

#include "apcs/animation/surface_fit.h"
#include "apcs/formats/inbetween_files.h"
#include "apcs/formats/path_files.h"
#include "apcs/raster/svg_encoder.h"
#include "session_pictures.h"
#include "apcs/screens/words.h"

#include <utility>

namespace apcs::step {

namespace text = words;

namespace {

// The path file as read, with its points replaced by the editor's in seven columns and its
// comments kept.
std::string rewritten_path_file(const SessionPath& path, const PathEditor& editor)
{
    const Expected<DatFile> original = parse_dat(path.text, editor.path_name());
    if (!original) {
        DatFile adjusted = dat_from(editor.points());
        adjusted.slopes = path.slopes;
        return format_dat(adjusted);
    }
    // SPEC §2.1: the slopes it was adjusted with go along, so that `apcs fit` regenerates the frames.
    return format_path_file(path.text, *original, editor.points(), editor.point_origins(), path.slopes);
}

} // namespace

// Initial_Graphics: steps 3–5 go on in graphics mode, in the PathEditor.
Shaping Shaping::after(const SlopesPrompt& slopes, StepContext& context)
{
    SessionModel& model = context.model;
    // The editor's document holds the path while it is shaped (the model's copy comes back when
    // it is accepted): one copy of a path of 10^6 points, not two.
    SessionPath& path = model.paths[static_cast<std::size_t>(slopes.path)];
    std::vector<std::vector<Vec3>> key_frames;
    for (const Graphic* key : {&model.keys.key1, &model.keys.key2})
        for (auto& polyline : key->polylines(key->all_points()))
            key_frames.push_back(std::move(polyline));
    return {slopes.path,
            PathEditor(PathEditor::Setup{{path.name, context.path_settings(slopes.path), model.view_angles,
                                          std::move(key_frames), context.settings.step,
                                          PictureRefinement{.when = context.settings.refinement,
                                                            .seen = context.settings.pictures_seen}},
                                         std::move(path.points),
                                         std::exchange(path.evaluation_room, {})},
                       context.files)};
}

StepResult Shaping::update(StepContext& context, const Command& command)
{
    if (editor.update(command) == PathEditor::Outcome::accepted)
        return accept(context);
    return {};
}

// Step 5: the path accepted is written back with its staff values.
StepResult Shaping::accept(StepContext& context)
{
    SessionPath& shaped = context.model.paths[static_cast<std::size_t>(path)];
    if (const Expected<void> written = context.write_file(editor.path_name(), rewritten_path_file(shaped, editor));
        !written) {
        editor.show_problem(written.error().to_string());
        return {};
    }
    context.model.written.add(editor.path_name());
    shaped.points = editor.points();
    context.files.log("accepted path " + editor.path_name() + " (rewritten with t c b a)");
    return {path == 0 ? StepOutcome::first_path_accepted : StepOutcome::last_path_accepted};
}

// Step 6 (fig. 4.2.7).

Lines AskStop::lines(const StepContext&) const { return {std::string(text::ask_stop)}; }

StepResult AskStop::submit(StepContext& context, const std::string&)
{
    context.say(std::string(text::fitting));
    return {StepOutcome::answered};
}

Lines Fitted::lines(const StepContext&) const { return {std::string(text::fitting_done), std::string(text::ask_draw)}; }

// s_fiting.c: the in-betweens fitted from both paths and written.
StepResult Fitted::start(StepContext& context)
{
    const SessionModel& model = context.model;
    frames = fit_key_frames(model.keys, evaluate_path(model.paths[0].points, context.path_settings(0)),
                            evaluate_path(model.paths[1].points, context.path_settings(1)), context.settings.surface);
    const Expected<std::vector<std::string>> written = context.files.write_inbetweens(frames, model.keys.key1);
    if (!written) {
        context.model.written.set_problem(written.error());
        return StepResult::refused(written.error().to_string());
    }
    for (const std::string& name : *written)
        context.model.written.add(name);
    context.files.log("surface fitting: " + std::to_string(written->size()) + " in-betweens of " +
                      std::to_string(model.point_count) + " points written");
    if (const std::optional<std::string> note = earlier_inbetweens_note(context.files.earlier_inbetweens(written->size()))) {
        context.say(*note);
        context.files.log(*note);
    }
    return {};
}

StepResult Fitted::submit(StepContext&, const std::string&) { return {StepOutcome::answered}; }

Playing Playing::after(Fitted& fitted, StepContext& context)
{
    const SessionModel& model = context.model;
    return {AnimationPlayer(std::move(fitted.frames), model.keys.key1, model.key_names, model.view_angles,
                            model.delay_ms, context.files),
            false};
}

StepResult Playing::update(StepContext& context, const Command& command)
{
    if (player.update(command) == AnimationPlayer::Outcome::finished)
        return {StepOutcome::done};
    if (player.leaf() == AnimationPlayer::State::overlaid && !overlay_written)
        write_overlay(context);
    return {};
}

// All frames overlaid, once, where --png, --png-raw and --svg asked for them.
void Playing::write_overlay(StepContext& context)
{
    overlay_written = true;
    const GraphicsScreen overlay = player.overlay_picture();
    const SessionSettings& settings = context.settings;
    for (const auto& [name, shape] :
         {std::pair{settings.overlay_png, PngShape::monitor}, std::pair{settings.overlay_png_raw, PngShape::raw}}) {
        if (name)
            write_picture(context, *name, overlay, shape, "overlay of all frames written to " + *name);
    }
    if (settings.overlay_svg)
        store_picture(context, *settings.overlay_svg, encode_svg(overlay),
                      "overlay of all frames written to " + *settings.overlay_svg);
}

} // namespace apcs::step
