#pragma once

#include "apcs/animation/path_change.h"
#include "apcs/animation/sampled_curve.h"
#include "apcs/animation/view_transform.h"
#include "apcs/raster/bitmap.h"

#include <optional>
#include <utility>
#include <vector>

namespace apcs {

// One line the curve draws, in raster pixels.
struct PixelLine {
    PixelPoint from;
    PixelPoint to;
};

// Segments first … end − 1 of a sampled curve as draw_world_curve draws them: emit(line) for each
// line in order, none kept. A line was drawn before when first > 0: a segment or sample that stays
// on the pixel where the lines stand is then passed over; a segment whose Bézier hull lies on that
// pixel is passed over whole (`from` is its start's pixel, so its other three hull points decide).
template <typename Emit>
void for_each_curve_line(const SampledCurve& curve, const ViewTransform& view, std::size_t first, std::size_t end,
                         Emit emit)
{
    if (first >= end || end > curve.segments.size())
        return;
    // A segment's samples projected a column at a time: most of drawing a long curve.
    SegmentSampleColumns samples(curve.basis);
    std::vector<int> pixel_x(curve.basis.size());
    std::vector<int> pixel_y(curve.basis.size());
    PixelPoint from = view.to_device(curve.segments[first].start).rounded();
    bool continuing = first > 0;
    const auto on_from = [&](const Vec3& point) { return view.to_device(point).rounded() == from; };
    for (std::size_t s = first; s < end; ++s) {
        const HermiteSegment& segment = curve.segments[s];
        if (continuing && on_from(segment.end) && on_from(segment.start + segment.start_tangent * (1.0 / 3.0)) &&
            on_from(segment.end - segment.end_tangent * (1.0 / 3.0)))
            continue;
        samples.sample(segment);
        view.to_pixels(samples.x, samples.y, samples.z, pixel_x, pixel_y);
        for (std::size_t j = 1; j < pixel_x.size(); ++j) {
            const PixelPoint to{pixel_x[j], pixel_y[j]};
            if (to == from && continuing)
                continue;
            emit(PixelLine{from, to});
            from = to;
            continuing = true;
        }
    }
}

// A KB curve drawn solid, as draw_world_curve draws it, kept between keys as one raster per block
// of consecutive segments: a key that changes a few segments of a path of 10^6 control points draws
// those blocks again and lays the others over them as they were. Blocks hold about
// block_segments(N) segments each (some 64 blocks; 4096 segments for 10^6); a control point
// inserted or deleted grows or shrinks the block it falls in, and the blocks after it keep their
// pixels, so that an edit costs a block's segments however many were made before it. A change of
// every segment draws all blocks again, on both cores. The pixels are draw_world_curve's for a curve that starts inside the clip (as
// a fitted view's does): a block's lines continue from its first segment's start, where the lines
// before it end. No strokes are recorded (the editor's screen is never written as SVG).
class CurveRaster {
public:
    // The curve's segments changed as `change` says since the last update.
    void splice(const SegmentSplice& change);
    // Draws the blocks changed; all of them when the view, the clip, the number of segments or of
    // samples per segment is not the last update's (after its splices). With `most_work`, only the
    // first of them, in path order, until about that much work is done (a line drawn or a segment
    // visited is one; rounds on both cores, each as large as the cost of the blocks drawn so far says
    // the rest of it allows): drawn() says whether every block is, and the pixels are those of the
    // blocks drawn (a scribbled path of 10^6 points takes 0.4 s to draw whole). A block that holds
    // any of the segments `unmade` (EvaluatedPath::segments_unmade) is not drawn: it stays stale and
    // its old pixels are not shown.
    void update(const SampledCurve& curve, const ViewTransform& view, PixelRect clip,
                std::size_t most_work = all_work, SegmentRange unmade = {});
    bool drawn() const { return blocks_drawn() == m_blocks.size(); }
    std::size_t blocks_drawn() const;
    std::size_t block_count() const { return m_blocks.size(); }
    // The work of every update since the raster was made (lines drawn and segments visited): an
    // edit's is a block's, however many edits came before it.
    std::size_t work_done() const { return m_work_done; }
    // The curve's pixels as of the last update (a 720x348 raster).
    const Bitmap& pixels() const { return m_composed; }

    static constexpr std::size_t all_work = static_cast<std::size_t>(-1);

    static constexpr std::size_t fewest_segments_per_block = 64;
    static constexpr std::size_t most_segments_per_block = 4096;
    // The blocks' size for a curve of `segment_count` segments: a 64th of them as a power of two,
    // between the two bounds above.
    static std::size_t block_segments(std::size_t segment_count);

private:
    struct Block {
        std::size_t segment_count = 0;
        bool current = false;
        Bitmap raster;
        // The rows its lines reach: first … end − 1.
        int first_row = 0;
        int end_row = 0;
    };

    void start_blocks(std::size_t segment_count);
    void split_large_blocks(std::vector<Bitmap> spare_rasters);
    // Blocks split by edits that grew the curve many times over are drawn afresh at its size.
    bool too_many_blocks() const;
    // Returns the work it did.
    std::size_t draw_block(Block& block, const SampledCurve& curve, std::size_t first_segment) const;
    // The stale blocks (block, its first segment) drawn, in rounds until `most_work` is done: how
    // many were drawn, from the first.
    std::size_t draw_stale_blocks(const std::vector<std::pair<std::size_t, std::size_t>>& stale, const SampledCurve& curve,
                                  std::size_t most_work);
    void compose();
    // The rows m_stale_rows laid again from the current blocks alone: an edit's few rows, not the
    // whole picture (an edit of a path of 16,000 points lays a few rows of its some 100 blocks).
    void compose_stale_rows();
    void add_stale_rows(const Block& block);

    std::vector<Block> m_blocks;
    std::size_t m_block_segments = fewest_segments_per_block;
    // The current blocks laid over one another, made again when one is drawn again; while no block
    // became stale since (m_composed_whole), blocks drawn are laid over it.
    Bitmap m_composed;
    bool m_composed_whole = false;
    // Rows first … end − 1 of m_composed that may hold the pixels of blocks no longer current.
    std::pair<int, int> m_stale_rows{0, 0};
    std::optional<ViewTransform> m_view;
    PixelRect m_clip;
    std::size_t m_segment_count = 0;
    int m_samples_per_segment = 0;
    std::size_t m_work_done = 0;
};

} // namespace apcs
