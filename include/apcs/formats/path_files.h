#pragma once

#include "apcs/animation/control_point.h"
#include "apcs/animation/graphic.h"
#include "apcs/formats/dat_file.h"
#include "apcs/formats/diagnostic.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace apcs {

// The name of graphic point K's path file (K from 1): "ani1.dat", "ani2.dat", …
std::string path_file_name(std::size_t point_number);

// The thesis' split.c (SPEC §5.2): one path file per graphic point, aniK.dat holding KEY1 point K
// and KEY2 point K, written atomically into `folder` (an existing differing file is kept as .bak).
// The keys must have equal point counts (equalised). Returns the files written, in order.
Expected<std::vector<std::filesystem::path>> split_into_path_files(const Graphic& key1, const Graphic& key2,
                                                                   const std::filesystem::path& folder);

// A path file for graphic point `which` ("first" or "last") must start at its KEY1 position and
// end at its KEY2 position (to 1e-6 of the scene's size). Returns the problem, if any, as
// "FILE:LINE: …" naming the expected point.
std::optional<Diagnostic> check_path_ends(const DatFile& path, const std::string& file_name, const std::string& which,
                                          const Vec3& key1_position, const Vec3& key2_position);

// A path file's control points with their staff values, as written back after adjusting (all
// seven columns).
DatFile dat_from(const ControlPoints& points);

// "(x, y, z)" with the shortest exact numbers, for messages.
std::string describe_point(const Vec3& point);

} // namespace apcs
