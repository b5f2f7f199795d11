#include "apcs/session/curve_raster.h"

#include "apcs/base/parallel_work.h"
#include "apcs/raster/painter.h"

#include <algorithm>
#include <cassert>

namespace apcs {

void CurveRaster::forget(std::size_t first_segment, std::size_t end_segment)
{
    if (first_segment >= end_segment)
        return;
    const std::size_t last_block = (end_segment - 1) / segments_per_block;
    for (std::size_t b = first_segment / segments_per_block; b <= last_block && b < m_blocks.size(); ++b)
        m_blocks[b].current = false;
}

void CurveRaster::forget_all()
{
    for (Block& block : m_blocks)
        block.current = false;
}

void CurveRaster::update(const SampledCurve& curve, const ViewTransform& view, PixelRect clip)
{
    const std::size_t segment_count = curve.segments.size();
    const std::size_t block_count = (segment_count + segments_per_block - 1) / segments_per_block;
    if (m_view != view || m_clip != clip || m_segment_count != segment_count ||
        m_samples_per_segment != curve.samples_per_segment || m_blocks.size() != block_count) {
        m_blocks.resize(block_count);
        forget_all();
        m_view = view;
        m_clip = clip;
        m_segment_count = segment_count;
        m_samples_per_segment = curve.samples_per_segment;
    }
    std::vector<std::size_t> stale;
    for (std::size_t b = 0; b < m_blocks.size(); ++b)
        if (!m_blocks[b].current)
            stale.push_back(b);
    if (stale.empty() && !m_blocks.empty())
        return;
    // Blocks are independent: a global change of 10^6 control points draws its 245 on two cores.
    split_across_cores(stale.size(), 1, [&](std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i)
            draw_block(m_blocks[stale[i]], curve, stale[i] * segments_per_block);
    });
    compose();
}

void CurveRaster::draw_block(Block& block, const SampledCurve& curve, std::size_t first_segment) const
{
    block.raster.clear();
    block.first_row = block.raster.height();
    block.end_row = 0;
    Painter painter(block.raster, m_clip);
    // Solid lines: the phase only says whether a line's first pixel is the last one's end.
    int phase = first_segment > 0 ? 1 : 0;
    for_each_curve_line(curve, *m_view, first_segment, std::min(first_segment + segments_per_block, m_segment_count),
                        [&](const PixelLine& line) {
                            painter.styled_line(line.from, line.to, LineStyle::solid, phase);
                            block.first_row = std::min({block.first_row, line.from.y, line.to.y});
                            block.end_row = std::max({block.end_row, line.from.y + 1, line.to.y + 1});
                        });
    block.current = true;
}

// A long trajectory's blocks each reach a few rows: only those are laid.
void CurveRaster::compose()
{
    m_composed.clear();
    for (const Block& block : m_blocks)
        m_composed.merge(block.raster, block.first_row, block.end_row);
}

void CurveRaster::draw(Bitmap& target) const
{
    assert(std::all_of(m_blocks.begin(), m_blocks.end(), [](const Block& block) { return block.current; }));
    target.merge(m_composed);
}

} // namespace apcs
