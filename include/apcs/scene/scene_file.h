#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/base/diagnostic.h"
#include "apcs/formats/dat_file.h"
#include "apcs/scene/scene.h"

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace apcs {

inline constexpr int max_scene_frames = 100000;
inline constexpr std::size_t max_scene_objects = 10000;

// Where a scene's .dat files come from: the name as the .scn file writes it → the file read.
// A failure is the file's own diagnostic ("key1.dat:3: …" or "key1.dat: no such file").
using SceneFileReader = std::function<Expected<DatFile>(const std::string& name)>;

// Reads a .scn file (SPEC §8.1–8.2) whose text is `text`, named `file_name` in messages; the .dat
// files it names come through `read`. `default_staff` are the staff values of three-column path
// files of objects without a STAFF of their own or of a parent (the command line's --tension …).
// Every problem is "FILE:LINE: message"; a bad .dat file's diagnostic follows the line that named it.
Expected<Scene> parse_scene(std::string_view text, const std::string& file_name, const SceneFileReader& read,
                            const StaffValues& default_staff);

// parse_scene on the file `name`, its .dat files named relative to the folder it is in (an
// absolute name as it is); "-" is standard input ("standard input:LINE" in messages), its files
// named relative to the current folder. The files read, the scene's own first, are added to
// `inputs` if given.
Expected<Scene> read_scene_file(const std::filesystem::path& name, const StaffValues& default_staff,
                                std::vector<std::filesystem::path>* inputs = nullptr);

// The default joint tolerance: 0.001 × the diagonal of the box around every frame-0 drawing.
double default_joint_tolerance(const Scene& scene);

} // namespace apcs
