#include "apcs/playback/animation_player.h"
#include "apcs/editor/path_editor.h"

#include "support/session_keys.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <tuple>

#include <string>
#include <vector>

using namespace apcs;
using apcs::test::apply;
using apcs::test::stick_player;
using apcs::test::LogLines;
using apcs::test::message_of;

// What the editor keeps of its setup has no points and no arrays: the document and the picture
// take them as it opens, and nothing can read them back empty.
template <typename Kept>
concept keeps_what_it_hands_over = requires(Kept kept) { kept.points; } || requires(Kept kept) { kept.evaluation_room; };
static_assert(!keeps_what_it_hands_over<PathEditor::Options> && keeps_what_it_hands_over<PathEditor::Setup>);
namespace cmd = apcs::command;

namespace {

PathEditor::Setup four_point_path()
{
    return apcs::test::path_setup({Vec3{0, 0, 0}, Vec3{3, -4, 5}, Vec3{1, 1, 7}, Vec3{0, 0, 10}},
                                  {{1, 1}, 8, 5, Spacing::nearest});
}

} // namespace

TEST_CASE("the path editor takes the staff line by line and is accepted when not adjusted again", "[session][editor]")
{
    LogLines log;
    PathEditor editor(four_point_path(), log);
    REQUIRE(editor.leaf() == PathEditor::State::control_choice);
    REQUIRE(editor.key_context() == KeyContext::control_choice);
    apply(editor, {cmd::ChooseGlobal{}});
    REQUIRE(editor.leaf() == PathEditor::State::staff);
    REQUIRE(message_of(editor.view()) == "way1.dat: TENSION  control points 1 to 4 of 4");
    apply(editor, {cmd::StaffStep{+3}, cmd::StaffStep{-1}, cmd::Accept{}});
    REQUIRE(message_of(editor.view()) == "way1.dat: CONTINUITY  control points 1 to 4 of 4");
    apply(editor, {cmd::StaffStep{+1}, cmd::Keep{}, cmd::StaffStep{-1}, cmd::Accept{}, cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::ask_again);
    REQUIRE(editor.update(cmd::No{}) == PathEditor::Outcome::accepted);
    for (const ControlPoint& point : editor.points())
        REQUIRE(point.staff == StaffValues{0.1, 0.0, -0.05, 0.0});
    REQUIRE(log.lines == std::vector<std::string>{"global control", "TENSION +0.10", "CONTINUITY +0.00 (kept)",
                                                  "BIAS -0.05", "ACCELERATION +0.00"});
}

TEST_CASE("each staff key leaves the path as evaluating its control points afresh gives, undo too", "[session][editor]")
{
    // Control points 2 and 3 differ in tension and continuity: the first key of a region on them,
    // even on the ACCELERATION line (Enter past the others), gives both the first one's shape.
    PathEditor::Setup setup = apcs::test::path_setup(
        {Vec3{0, 0, 0}, Vec3{3, -4, 5}, Vec3{1, 1, 7}, Vec3{0, 0, 10}, Vec3{2, 3, 12}, Vec3{5, 1, 14}},
        {{1, 1}, 8, 5, Spacing::nearest});
    setup.points[2].staff = {0.6, -0.4, 0, 0};
    const PathSettings settings = setup.settings;
    LogLines log;
    PathEditor editor(std::move(setup), log);
    const auto matches_fresh = [&](const char* after) {
        CAPTURE(after);
        const EvaluatedPath fresh = evaluate_path(editor.points(), settings);
        REQUIRE(editor.evaluated().curve.segments == fresh.curve.segments);
        REQUIRE(editor.evaluated().curve.segment_length == fresh.curve.segment_length);
        REQUIRE(editor.evaluated().curve.length_to_point == fresh.curve.length_to_point);
        REQUIRE(editor.evaluated().inbetweens.size() == fresh.inbetweens.size());
        for (std::size_t j = 0; j < fresh.inbetweens.size(); ++j)
            REQUIRE(editor.evaluated().inbetweens[j].position == fresh.inbetweens[j].position);
    };
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{1}, cmd::ArrowMove{1}, cmd::Accept{}, cmd::ArrowMove{1},
                   cmd::ArrowMove{1}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}});
    REQUIRE(message_of(editor.view()) == "way1.dat: ACCELERATION  control points 2 to 4 of 6");
    apply(editor, {cmd::StaffStep{+4}});
    REQUIRE(editor.points()[2].staff == StaffValues{0, 0, 0, 0.2});
    matches_fresh("the first key on ACCELERATION, which gave point 3 point 2's tension and continuity");
    apply(editor, {cmd::StaffStep{+4}});
    matches_fresh("a key on ACCELERATION alone");
    apply(editor, {cmd::Undo{}});
    matches_fresh("undoing the second key");
    apply(editor, {cmd::Undo{}});
    REQUIRE(editor.points()[2].staff == StaffValues{0.6, -0.4, 0, 0});
    matches_fresh("undoing the first key");
    apply(editor, {cmd::Accept{}, cmd::Yes{}, cmd::ChooseGlobal{}, cmd::StaffStep{-3}});
    matches_fresh("a global key on TENSION");
}

TEST_CASE("a long path's screen, kept block by block between keys, is the screen drawn afresh", "[session][editor]")
{
    // 10000 control points (three blocks of segments) zigzagging over the screen, so that most
    // samples fall on pixels of their own and blocks meet in the middle of lines.
    PathEditor::Setup setup;
    setup.path_name = "way1.dat";
    for (int k = 0; k < 10000; ++k)
        setup.points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.001, std::cos(k * 0.37) * 2.0}, {}});
    setup.settings = {{1, 1}, 8, 12, Spacing::nearest};
    LogLines log;
    PathEditor editor(std::move(setup), log);
    // The kept picture against a fresh one: without the ghost (O), which a fresh draw has not.
    apply(editor, {cmd::ToggleGhost{}});
    const auto matches_fresh = [&](const char* after) {
        CAPTURE(after);
        PathScreenContent fresh = path_screen_content(editor.points(), editor.evaluated());
        const GraphicsScreen drawn = draw_path_screen(fresh, editor.view_transform());
        REQUIRE(editor.view().bitmap == drawn.bitmap);
        REQUIRE(editor.view().bitmap.lit_count() > 20000);
    };
    matches_fresh("opening");
    const Bitmap opened = editor.view().bitmap;
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{1}, cmd::ArrowMove{4089}, cmd::Accept{}, cmd::ArrowMove{15},
                   cmd::Accept{}, cmd::StaffStep{-20}});
    REQUIRE(editor.points()[4096].staff.tension == Approx(-1.0));
    REQUIRE(editor.view().bitmap != opened);
    matches_fresh("a local key on control points 4090 to 4105, across two blocks");
    apply(editor, {cmd::Undo{}});
    matches_fresh("its undo");
    apply(editor, {cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Yes{}, cmd::ChooseGlobal{},
                   cmd::StaffStep{+5}});
    matches_fresh("a global key");
}

TEST_CASE("a scribbled path's control points, one mark per pixel, show what a mark per point shows",
          "[session][editor]")
{
    PathEditor::Setup setup;
    setup.path_name = "way1.dat";
    for (int k = 0; k < 10000; ++k)
        setup.points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.001, std::cos(k * 0.37) * 2.0}, {}});
    LogLines log;
    PathEditor editor(std::move(setup), log);
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{1}, cmd::ArrowMove{3999}, cmd::Accept{}, cmd::ArrowMove{2000},
                   cmd::Accept{}, cmd::StaffStep{+2}});
    const GraphicsScreen shown = editor.view();
    GraphicsScreen every = shown;
    std::erase_if(every.marks, [](const PixelMark& mark) { return mark.kind == MarkKind::control_point; });
    for (std::size_t k = 0; k < editor.points().size(); ++k)
        every.marks.push_back({editor.view_transform().to_device(editor.points()[k].position).rounded(),
                               MarkKind::control_point, k >= 4000 && k <= 6000 ? CellStyle::reverse : CellStyle::plain,
                               k >= 4000 && k <= 6000 ? ColourRole::region : ColourRole::monitor});
    const auto control_marks = [](const GraphicsScreen& screen) {
        return std::count_if(screen.marks.begin(), screen.marks.end(),
                             [](const PixelMark& mark) { return mark.kind == MarkKind::control_point; });
    };
    REQUIRE(control_marks(shown) < 9500); // 9152: points that share a pixel show one mark
    REQUIRE(control_marks(every) == 10000);
    for (const CellArea area : {CellArea{80, 24}, CellArea{200, 60}})
        for (const GlyphSet glyphs : {GlyphSet::ascii, GlyphSet::braille}) {
            CAPTURE(area.columns);
            REQUIRE(render_cells(shown, area, glyphs) == render_cells(every, area, glyphs));
        }
    REQUIRE(render_raster(shown) == render_raster(every));
}

TEST_CASE("the region's arrow starts at the first control point and cannot leave the path", "[session][editor]")
{
    LogLines log;
    PathEditor editor(four_point_path(), log);
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{-1}, cmd::ArrowMove{-1}, cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::region_last);
    apply(editor, {cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::ArrowMove{+1}, cmd::Accept{}});
    REQUIRE(editor.leaf() == PathEditor::State::staff);
    REQUIRE(log.lines.back() == "local control: control points 1 to 4");
}

TEST_CASE("Esc while picking goes one step back, Y after the staff to the control choice", "[session][editor]")
{
    LogLines log;
    PathEditor editor(four_point_path(), log);
    apply(editor, {cmd::ChooseLocal{}, cmd::ArrowMove{+1}, cmd::Accept{}, cmd::Back{}});
    REQUIRE(editor.leaf() == PathEditor::State::region_first);
    apply(editor, {cmd::Back{}});
    REQUIRE(editor.leaf() == PathEditor::State::control_choice);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Yes{}});
    REQUIRE(editor.leaf() == PathEditor::State::control_choice);
}

TEST_CASE("a path that could not be written is asked about again with the reason shown", "[session][editor]")
{
    LogLines log;
    PathEditor editor(four_point_path(), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}});
    REQUIRE(editor.update(cmd::No{}) == PathEditor::Outcome::accepted);
    editor.show_problem("way1.dat: cannot write: Read-only file system");
    REQUIRE(editor.leaf() == PathEditor::State::ask_again);
    REQUIRE(message_of(editor.view()) == "way1.dat: cannot write: Read-only file system");
}

TEST_CASE("the animation player shows one frame per tick, then all frames, then finishes", "[session][animation]")
{
    LogLines log;
    AnimationPlayer player = stick_player(log);
    REQUIRE(player.playing());
    REQUIRE(message_of(player.view()) == "KEY1: k1.dat");
    player.tick();
    REQUIRE(player.update(cmd::Pause{}) == AnimationPlayer::Outcome::showing);
    player.tick();
    REQUIRE(message_of(player.view()) == "In-between 1 of 1: inb001.dat  (paused)");
    player.update(cmd::Replay{});
    REQUIRE(message_of(player.view()) == "KEY1: k1.dat");
    player.tick();
    player.tick();
    REQUIRE(message_of(player.view()) == "KEY2: k2.dat");
    player.tick();
    REQUIRE(player.leaf() == AnimationPlayer::State::stopped);
    REQUIRE(player.key_context() == KeyContext::any_key_graphics);
    REQUIRE(player.update(cmd::Continue{}) == AnimationPlayer::Outcome::showing);
    REQUIRE(player.leaf() == AnimationPlayer::State::overlaid);
    REQUIRE(player.update(cmd::Continue{}) == AnimationPlayer::Outcome::finished);
    REQUIRE(log.lines == std::vector<std::string>{"animation: 3 frames, 50 ms each", "showed all 3 frames overlaid"});
}

TEST_CASE("comma and full stop pause the animation and step a frame back and on, within the frames",
          "[session][animation]")
{
    LogLines log;
    AnimationPlayer player = stick_player(log);
    REQUIRE(player.update(cmd::StepFrame{+1}) == AnimationPlayer::Outcome::showing);
    REQUIRE_FALSE(player.playing());
    REQUIRE(message_of(player.view()) == "In-between 1 of 1: inb001.dat  (paused)");
    player.tick();
    REQUIRE(message_of(player.view()) == "In-between 1 of 1: inb001.dat  (paused)");
    player.update(cmd::StepFrame{+1});
    player.update(cmd::StepFrame{+1});
    REQUIRE(message_of(player.view()) == "KEY2: k2.dat  (paused)");
    REQUIRE(player.leaf() == AnimationPlayer::State::paused);
    player.update(cmd::StepFrame{-1});
    player.update(cmd::StepFrame{-1});
    player.update(cmd::StepFrame{-1});
    REQUIRE(message_of(player.view()) == "KEY1: k1.dat  (paused)");
    player.update(cmd::Pause{});
    REQUIRE(player.playing());
    REQUIRE(command_for(KeyContext::animation, KeyEvent::typed(U',')) == Command{cmd::StepFrame{-1}});
    REQUIRE(command_for(KeyContext::animation, KeyEvent::typed(U'.')) == Command{cmd::StepFrame{+1}});
}

TEST_CASE("a long path's screen and numbers, kept across waypoint keys and exact spacing, are those drawn and "
          "evaluated afresh",
          "[session][editor][waypoints]")
{
    for (const Spacing spacing : {Spacing::nearest, Spacing::exact}) {
        CAPTURE(static_cast<int>(spacing));
        PathEditor::Setup setup;
        setup.path_name = "way1.dat";
        for (int k = 0; k < 10000; ++k)
            setup.points.push_back({{std::sin(k * 0.9) * 3.0, k * 0.001, std::cos(k * 0.37) * 2.0}, {}});
        setup.settings = {{1, 1}, 8, 12, spacing};
        const PathSettings settings = setup.settings;
        LogLines log;
        PathEditor editor(std::move(setup), log);
        apply(editor, {cmd::ToggleGhost{}}); // a fresh draw has no ghost
        // `region`: the one boxed (the waypoint editor's chosen point is read from its message).
        const auto matches_fresh = [&](const char* after, std::optional<ControlRegion> region) {
            CAPTURE(after);
            const EvaluatedPath fresh = evaluate_path(editor.points(), settings);
            REQUIRE(editor.evaluated().curve.segments == fresh.curve.segments);
            REQUIRE(editor.evaluated().curve.length_to_point == fresh.curve.length_to_point);
            REQUIRE(editor.evaluated().inbetweens.size() == fresh.inbetweens.size());
            for (std::size_t j = 0; j < fresh.inbetweens.size(); ++j)
                REQUIRE(editor.evaluated().inbetweens[j].position == fresh.inbetweens[j].position);
            const GraphicsScreen shown = editor.view();
            PathScreenContent content = path_screen_content(editor.points(), fresh);
            content.region = region;
            if (editor.leaf() == PathEditor::State::waypoints) {
                // The waypoint editor boxes its chosen point: "control point N of M  depth …".
                const std::size_t chosen = std::stoul(message_of(shown).substr(std::string("control point ").size())) - 1;
                content.region = ControlRegion{chosen, chosen};
            }
            const GraphicsScreen drawn = draw_path_screen(content, editor.view_transform());
            REQUIRE(shown.bitmap == drawn.bitmap);
            const auto control_marks = [](const GraphicsScreen& screen) {
                std::vector<std::tuple<int, int, CellStyle>> marks;
                for (const PixelMark& mark : screen.marks)
                    if (mark.kind == MarkKind::control_point)
                        marks.emplace_back(mark.at.x, mark.at.y, mark.style);
                return marks;
            };
            REQUIRE(control_marks(shown).size() == control_marks(drawn).size());
            REQUIRE((control_marks(shown) == control_marks(drawn)));
        };
        apply(editor, {cmd::ChooseGlobal{}, cmd::StaffStep{+3}});
        matches_fresh("a global key", ControlRegion{0, 9999});
        apply(editor, {cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::StaffStep{-2}});
        matches_fresh("a global key on ACCELERATION", ControlRegion{0, 9999});
        apply(editor, {cmd::Accept{}, cmd::Yes{}, cmd::ChooseLocal{}, cmd::ArrowMove{1}, cmd::ArrowMove{4094},
                       cmd::Accept{}, cmd::ArrowMove{3}, cmd::Accept{}, cmd::StaffStep{-4}});
        matches_fresh("a local key across two blocks", ControlRegion{4094, 4097});
        apply(editor, {cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}, cmd::Yes{}, cmd::OpenWaypoints{},
                       cmd::ChoosePoint{4095}, cmd::MovePoint{2, -1, 1}});
        matches_fresh("a waypoint moved", std::nullopt);
        apply(editor, {cmd::InsertPoint{}, cmd::InsertPoint{}});
        matches_fresh("two waypoints inserted", std::nullopt);
        apply(editor, {cmd::ChoosePoint{-3}, cmd::DeletePoint{}, cmd::ChoosePoint{4000}, cmd::DeletePoint{}});
        matches_fresh("two waypoints deleted, one in the last block", std::nullopt);
        apply(editor, {cmd::Undo{}});
        matches_fresh("a deletion undone in the waypoint editor", std::nullopt);
        apply(editor, {cmd::Accept{}});
        matches_fresh("the waypoints kept", std::nullopt);
        apply(editor, {cmd::Undo{}, cmd::Undo{}});
        matches_fresh("two waypoint changes undone after", std::nullopt);
        apply(editor, {cmd::OpenWaypoints{}, cmd::InsertPoint{}, cmd::MovePoint{0, 3, 0}, cmd::Back{}});
        matches_fresh("waypoint changes discarded with Esc", std::nullopt);
    }
}

TEST_CASE("the message line names the frames that freeze as the staff makes them", "[session][editor]")
{
    // A straight path of 4 samples and 3 in-betweens. At acceleration +1 the targets are
    // 1 − cos(πτ/2) = 0.076, 0.293, 0.617 of the length: the first is nearest sample 0, KEY1 itself.
    LogLines log;
    PathEditor editor(apcs::test::path_setup({Vec3{0, 0, 0}, Vec3{0, 8, 0}}, {{1, 1}, 4, 3, Spacing::nearest}), log);
    apply(editor, {cmd::ChooseGlobal{}, cmd::Accept{}, cmd::Accept{}, cmd::Accept{}});
    REQUIRE(message_of(editor.view()) == "way1.dat: ACCELERATION  control points 1 to 2 of 2");
    apply(editor, {cmd::StaffStep{+20}});
    REQUIRE(message_of(editor.view()) ==
            "way1.dat: ACCELERATION  frames will freeze at KEY1=1");
    apply(editor, {cmd::StaffStep{-20}});
    REQUIRE(message_of(editor.view()) == "way1.dat: ACCELERATION  control points 1 to 2 of 2  only the in-betweens moved");
}
