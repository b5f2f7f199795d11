#pragma once

#include "apcs/animation/sampled_curve.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/painter.h"

#include <optional>
#include <vector>

namespace apcs {

// One line the curve draws, in raster pixels.
struct PixelLine {
    PixelPoint from;
    PixelPoint to;
};

// The lines draw_world_curve draws for a KB curve, found block by block of segments and kept
// between keys: a key that changes a few segments of a path of 10^6 control points finds those
// blocks' lines again and replays the rest, the same lines in the same order (so the same pixels,
// dashes and strokes). A change of every segment finds all blocks again, on both cores.
class CurveLines {
public:
    // The curve's segments first … end − 1 have changed since the last update.
    void forget(std::size_t first_segment, std::size_t end_segment);
    // The control points moved, or their number changed.
    void forget_all();
    // Finds the lines of the blocks forgotten; all of them when the view, the number of segments
    // or of samples per segment is not the last update's.
    void update(const SampledCurve& curve, const ViewTransform& view);
    // Draws the lines as draw_world_curve would.
    void draw(Painter& painter, LineStyle style = LineStyle::solid) const;

    static constexpr std::size_t segments_per_block = 4096;

private:
    struct Block {
        bool current = false;
        std::vector<PixelLine> lines;
    };

    std::vector<Block> m_blocks;
    std::optional<ViewTransform> m_view;
    std::size_t m_segment_count = 0;
    int m_samples_per_segment = 0;
};

// Segments first … end − 1 of a sampled curve as draw_world_curve draws them: the lines in order.
// `continuing` says a line was drawn before (first > 0): a segment or sample that stays on the
// pixel where the lines stand is then passed over.
void find_curve_lines(const SampledCurve& curve, const ViewTransform& view, std::size_t first, std::size_t end,
                      std::vector<PixelLine>& lines);

} // namespace apcs
