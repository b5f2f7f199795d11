#include "figures_command.h"

#include "apcs/animation/surface_fit.h"
#include "apcs/base/utf8.h"
#include "apcs/cli/data_folder.h"
#include "apcs/cli/path_command.h"
#include "report.h"
#include "apcs/formats/file_io.h"
#include "apcs/formats/numbered_files.h"
#include "apcs/formats/path_files.h"
#include "apcs/scene/scene_animation.h"
#include "apcs/scene/scene_file.h"
#include "apcs/scene/scene_joints.h"
#include "apcs/screens/figures.h"
#include "apcs/screens/surface_figures.h"

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace apcs {

const std::vector<ExampleFigure>& example_figures()
{
    static const std::vector<ExampleFigure> figures{
        {"n-to-l", "way1.dat", "way4.dat", {0, 90}, "example-1-n-to-l-a.png", "Fig. 5.1.a  N becomes L, THETA 0 PHI 90"},
        {"n-to-l", "way1.dat", "way4.dat", {30, 40}, "example-1-n-to-l-b.png", "Fig. 5.1.b  N becomes L, THETA 30 PHI 40"},
        {"stick", "way1.dat", "way5.dat", {0, 90}, "example-2-stick-a.png", "Fig. 5.2.a  A stick falls, THETA 0 PHI 90"},
        {"stick", "way1.dat", "way5.dat", {40, 50}, "example-2-stick-b.png", "Fig. 5.2.b  A stick falls, THETA 40 PHI 50"},
        {"snake-apple", "way1.dat", "way7.dat", {0, 90}, "example-3-snake-apple.png",
         "Example 3  A snake moves toward an apple, THETA 0 PHI 90", "apple.dat"},
    };
    return figures;
}

namespace {

// An example's keys as read and equalised, and its shipped paths evaluated (3 columns: staff values 0).
Expected<SurfaceFigureSource> read_example(const ExampleFigure& example, const std::filesystem::path& data_folder,
                                           const CommonOptions& options)
{
    const std::filesystem::path folder = data_folder / example.folder;
    const Expected<Graphic> key1 = read_key_frame(folder / "key1.dat");
    if (!key1)
        return key1.error();
    const Expected<Graphic> key2 = read_key_frame(folder / "key2.dat");
    if (!key2)
        return key2.error();
    SurfaceFigureSource source{*key1, *key2, equalise_key_frames(*key1, *key2), {}, {}};
    for (const auto& [name, end] : {std::pair{example.path_first, PathEnd::first}, std::pair{example.path_last, PathEnd::last}}) {
        const Expected<DatFile> file = read_dat_file(folder / name);
        if (!file)
            return file.error();
        const Expected<ControlPoints> points =
            point_path_from(*file, (folder / name).string(), end, source.keys, options.staff);
        if (!points)
            return points.error();
        (end == PathEnd::first ? source.first_path : source.last_path) = evaluate_path(*points, options.path);
    }
    return source;
}

// The example's frames, its still objects drawn once.
Expected<GraphicsScreen> draw_example(const ExampleFigure& example, const std::filesystem::path& data_folder,
                                      const CommonOptions& options)
{
    const Expected<SurfaceFigureSource> source = read_example(example, data_folder, options);
    if (!source)
        return source.error();
    std::vector<Graphic> still;
    if (!example.still_file.empty()) {
        Expected<Graphic> object = read_key_frame(data_folder / example.folder / example.still_file);
        if (!object)
            return object.error();
        still.push_back(std::move(*object));
    }
    const FrameSequence frames = fit_key_frames(source->keys, source->first_path, source->last_path);
    return draw_frames_figure(example.title, frames, source->keys.key1, example.view, still);
}

// Both surface constructions side by side on Example 1 (N becomes L), in fig. 5.1.a's view.
Expected<GraphicsScreen> draw_surfaces_example(const std::filesystem::path& data_folder, const CommonOptions& options)
{
    const ExampleFigure n_to_l{"n-to-l", "way1.dat", "way4.dat", {0, 90}, "", ""};
    const Expected<SurfaceFigureSource> source = read_example(n_to_l, data_folder, options);
    if (!source)
        return source.error();
    return draw_surfaces_figure("Example 1  N becomes L by both surfaces, THETA 0 PHI 90", *source, n_to_l.view);
}

// "neck: head point 1 = torso point 7", the part declared first first.
std::string joint_legend(const Scene& scene, const std::string& name, const JointEnds& ends)
{
    const auto end_text = [&scene](const JointEnd& end) {
        return scene.objects[end.object].name + " " + joint_points_text(end.first, end.last);
    };
    return name + ": " + end_text(ends.earlier) + " = " + end_text(ends.later);
}

// Fig. 3.3.3: the robot of data/robot standing at frame 0, its neck joint A and wrist joint B marked.
// The scene is read and checked as apcs play reads and checks it, every frame's closing joints
// too: a robot that play refuses is not drawn as if it were whole.
Expected<GraphicsScreen> draw_robot_figure(const std::filesystem::path& data_folder, const CommonOptions& options)
{
    const std::filesystem::path file = data_folder / "robot" / "robot.scn";
    const Expected<Scene> scene = read_scene_file(file, options.staff);
    if (!scene)
        return scene.error();
    const SceneAnimation animation(*scene, scene_path_settings(*scene, options.path, options.given.spacing));
    if (Expected<void> closed = check_closing_joints(*scene, animation, file.string()); !closed)
        return closed.error();
    const std::vector<Vec3> points = animation.frame(0);
    std::vector<FigureMark> marks;
    for (const auto& [label, joint] : {std::pair{"A", "neck"}, std::pair{"B", "wrist-r"}}) {
        const std::optional<JointEnds> ends = find_joint(*scene, joint);
        if (!ends)
            return Diagnostic{file.string(), 0, std::string("has no joint ") + joint + "; fig. 3.3.3 marks the neck and a wrist"};
        const ObjectPoints earlier = animation.object_points()[ends->earlier.object];
        const Vec3 position = joint_place(std::span<const Vec3>(points).subspan(earlier.first, earlier.count),
                                          ends->earlier.first, ends->earlier.last);
        marks.push_back({label, position, joint_legend(*scene, joint, *ends)});
    }
    return draw_marked_frame_figure("Fig. 3.3.3  The robot: key points A (neck) and B (wrist)", points,
                                    animation.structure(), scene->view.value_or(ViewAngles{0, 90}), marks);
}

} // namespace

ExitStatus run_figures_command(const CommonOptions& options, const std::filesystem::path& data_folder, std::ostream& out,
                               std::ostream& err)
{
    const std::filesystem::path target = options.out.value_or(".");
    // Every picture is drawn before the first is written: examples that cannot be read leave the
    // folder as it was, not with some of the figures.
    std::vector<std::pair<std::string, GraphicsScreen>> pictures;
    for (const CurveFigure& figure : thesis_curve_figures())
        pictures.emplace_back(figure.file_name, draw_curve_figure(figure));
    const std::filesystem::path examples = options.workdir.empty() ? data_folder : options.workdir;
    for (const ExampleFigure& example : example_figures()) {
        Expected<GraphicsScreen> screen = draw_example(example, examples, options);
        if (!screen)
            return report_bad_input(screen.error(), err);
        pictures.emplace_back(example.file_name, std::move(*screen));
    }
    pictures.emplace_back("fig-3-2-1.png", draw_ferguson_figure("Fig. 3.2.1  Surface fitting on a Ferguson surface",
                                                                thesis_surface_example(options.path), {20, 70}));
    Expected<GraphicsScreen> surfaces = draw_surfaces_example(examples, options);
    if (!surfaces)
        return report_bad_input(surfaces.error(), err);
    pictures.emplace_back("example-1-n-to-l-surfaces.png", std::move(*surfaces));
    Expected<GraphicsScreen> robot = draw_robot_figure(examples, options);
    if (!robot)
        return report_bad_input(robot.error(), err);
    pictures.emplace_back("fig-3-3-3.png", std::move(*robot));
    if (Expected<void> made = make_output_folder(target, "the figures"); !made)
        return report_bad_input(made.error(), err);
    const PngInk ink = options.paper ? PngInk::paper : PngInk::monitor;
    for (const auto& [name, screen] : pictures) {
        if (Expected<void> done =
                write_png_file(target / name, screen, PngShape::monitor, read_files_guard(options), out, ink);
            !done)
            return report_bad_input(done.error(), err);
        out << escape_controls((target / name).string()) << '\n';
    }
    return ExitStatus::success;
}

ExitStatus run_figures_command(const CommonOptions& options, std::ostream& out, std::ostream& err)
{
    if (!options.workdir.empty())
        return run_figures_command(options, options.workdir, out, err);
    const Expected<std::filesystem::path> examples = find_data_folder();
    if (!examples)
        return report_bad_input(examples.error(), err);
    return run_figures_command(options, *examples, out, err);
}

} // namespace apcs
