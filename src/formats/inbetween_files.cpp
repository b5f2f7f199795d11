#include "apcs/formats/inbetween_files.h"

#include "apcs/base/utf8.h"
#include "apcs/formats/dat_file.h"
#include "apcs/formats/numbered_files.h"
#include "apcs/formats/path_files.h"

#include <algorithm>
#include <functional>
#include <optional>

namespace apcs {

namespace {

// In-betweens 1 … count, each made a chunk of points at a time by points_of(frame, first, out),
// headed and formatted with `decimals`, written one file per core.
Expected<std::vector<std::filesystem::path>>
write_inbetweens(std::size_t count, std::size_t point_count, int decimals, const Graphic& structure,
                 const std::function<void(std::size_t frame, std::size_t first, std::span<Vec3> out)>& points_of,
                 const std::filesystem::path& folder, const KeyFileGuard& guard, const WriteProgress& progress)
{
    const auto write_frame = [&](std::size_t index, const ContentSink& sink) {
        const std::size_t frame = index + 1;
        if (!sink(inbetween_heading(frame, count)))
            return;
        const auto points_at = [&points_of, frame](std::size_t first, std::span<Vec3> out) { points_of(frame, first, out); };
        format_graphic_in_chunks(structure, point_count, points_at, decimals, sink);
    };
    return write_numbered_files(
        folder, count, [](std::size_t index) { return inbetween_file_name(index + 1); }, write_frame, guard,
        "the in-between files", progress);
}

} // namespace

Expected<std::vector<std::filesystem::path>> write_inbetween_files(const FrameSequence& frames, const Graphic& structure,
                                                                   const std::filesystem::path& folder,
                                                                   const KeyFileGuard& guard, const WriteProgress& progress)
{
    const auto copy_points = [&frames](std::size_t frame, std::size_t first, std::span<Vec3> out) {
        const std::span<const Vec3> points = frames.frame(frame).subspan(first, out.size());
        std::copy(points.begin(), points.end(), out.begin());
    };
    return write_inbetweens(inbetween_count(frames), frames.points_per_frame(), inbetween_decimals(frames), structure,
                            copy_points, folder, guard, progress);
}

Expected<std::vector<std::filesystem::path>> write_inbetween_files(const SurfaceFitter& fitter, const Graphic& structure,
                                                                   const std::filesystem::path& folder,
                                                                   const KeyFileGuard& guard, const WriteProgress& progress)
{
    const std::size_t count = fitter.frame_count() < 2 ? 0 : fitter.frame_count() - 2;
    const auto fit_points = [&fitter](std::size_t frame, std::size_t first, std::span<Vec3> out) {
        fitter.fit(frame, first, out);
    };
    return write_inbetweens(count, fitter.point_count(), inbetween_decimals(fitter.key1(), fitter.key2()), structure,
                            fit_points, folder, guard, progress);
}

std::vector<std::string> inbetweens_beyond(std::span<const std::string> names, std::size_t written_count)
{
    return numbered_names(names, "inb", ".dat",
                          [written_count](std::size_t number, const std::string&) { return number > written_count; });
}

std::vector<std::string> inbetweens_beyond(const std::filesystem::path& folder, std::size_t written_count)
{
    return inbetweens_beyond(file_names_in(folder), written_count);
}

std::optional<std::string> earlier_inbetweens_note(std::span<const std::string> earlier)
{
    if (earlier.empty())
        return std::nullopt;
    // Printed on stderr and in apcs.log: the folder's name in them is the user's, escaped.
    if (earlier.size() == 1)
        return escape_controls(earlier.front()) + " is from an earlier run (not rewritten)";
    return escape_controls(earlier.front()) + " to " + escape_controls(earlier.back()) + " (" +
           std::to_string(earlier.size()) + " files) are from an earlier run (not rewritten)";
}

} // namespace apcs
