#include "inbetween_command.h"

#include "apcs/animation/add_points.h"
#include "apcs/animation/memory_budget.h"
#include "frame_output.h"
#include "memory_limit.h"
#include "report.h"
#include "apcs/formats/file_io.h"

#include <algorithm>
#include <array>
#include <ostream>

namespace apcs {

namespace {

// Both key frames with the same point count, and the parts the frames are written with.
struct PaddedKeys {
    std::vector<Vec3> begin;
    std::vector<Vec3> end;
    Graphic structure;
};

PaddedKeys pad_keys(const Graphic& key1, const Graphic& key2, Padding padding)
{
    if (padding == Padding::apcs) {
        const EqualisedKeys keys = equalise_key_frames(key1, key2);
        return {keys.key1.all_points(), keys.key2.all_points(), keys.key1};
    }
    // The 2003 paper pads one polyline: the frames are written as a single open part.
    std::vector<Vec3> begin = key1.all_points();
    std::vector<Vec3> end = key2.all_points();
    if (begin.size() < end.size())
        begin = pad_points(begin, end.size(), padding);
    else
        end = pad_points(end, begin.size(), padding);
    Graphic structure;
    structure.parts.push_back({"", Closure::open, begin});
    return {std::move(begin), std::move(end), std::move(structure)};
}

} // namespace

ExitStatus run_inbetween_command(const InbetweenSettings& settings, const CommonOptions& options, std::ostream& out,
                                 std::ostream& err)
{
    const Expected<Graphic> key1 = read_key_frame(settings.key1);
    if (!key1)
        return report_bad_input(key1.error(), err);
    const Expected<Graphic> key2 = read_key_frame(settings.key2);
    if (!key2)
        return report_bad_input(key2.error(), err);
    const int intervals = settings.frame_intervals.value_or(options.path.inbetween_count + 1);
    // Both keys are padded to the larger point count.
    const memory::FramesRequest request{static_cast<std::size_t>(intervals) + 1,
                                        std::max(key1->point_count(), key2->point_count()), options.print};
    if (const auto refused = refuse_over_budget(memory::describe(request), memory::frames_bytes(request), options,
                                                "lower --frames or --inbetweens, or use key frames of fewer points", err))
        return *refused;
    const PaddedKeys keys = pad_keys(*key1, *key2, settings.padding);
    const FrameSequence frames = interpolate_frames(keys.begin, keys.end, intervals, settings.law);
    const std::array<std::filesystem::path, 2> key_files{settings.key1, settings.key2};
    return deliver_frames(frames, keys.structure, options, key_files, out, err);
}

} // namespace apcs
