#include "apcs/screens/curve_raster.h"

#include "apcs/base/parallel_work.h"
#include "apcs/raster/line_pixels.h"
#include "apcs/raster/painter.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>
#include <utility>

namespace apcs {

namespace {

// A line inside the clip as Painter::styled_line lights it solid: Bresenham's pixels from one end
// to the other but the first once the polyline has begun (phase > 0), without the clipping, the
// pattern and the strokes a painter minds. A scribbled path draws 10^8 such pixels; a run along a
// row (most of a scribble's lines in a view from the front) is lit a byte at a time.
void light_solid_line(Bitmap& raster, const PixelLine& line, PixelRect box, int& phase)
{
    bool skip_first = phase > 0;
    if (line.from.y == line.to.y) {
        int first = line.from.x;
        const int last = line.to.x;
        if (skip_first && first == last)
            return;
        if (skip_first)
            first += first < last ? 1 : -1;
        raster.set_run(line.from.y, first, last);
        phase += std::abs(last - first) + 1;
        return;
    }
    each_line_pixel(line.from, line.to, box, [&](int x, int y) {
        if (std::exchange(skip_first, false))
            return;
        raster.set(x, y, true);
        ++phase;
    });
}

} // namespace

// A change that removes no segment lies in the block it starts in (the last, at the curve's end).
void CurveRaster::splice(const SegmentSplice& change)
{
    // An acceleration changes no segment: no block is drawn again.
    if (m_blocks.empty() || (change.removed == 0 && change.inserted == 0))
        return;
    std::size_t block_first = 0;
    bool inserted_placed = false;
    for (Block& block : m_blocks) {
        const std::size_t block_end = block_first + block.segment_count;
        const std::size_t from = std::max(block_first, change.first);
        const std::size_t to = std::min(block_end, change.old_end());
        const bool holds_start = change.first >= block_first && (change.first < block_end || &block == &m_blocks.back());
        block_first = block_end;
        if (from >= to && !(change.removed == 0 && holds_start))
            continue;
        if (block.current)
            add_stale_rows(block);
        block.current = false;
        block.segment_count -= from < to ? to - from : 0;
        if (!inserted_placed)
            block.segment_count += change.inserted;
        inserted_placed = true;
    }
    // The rasters of the blocks the change emptied serve the blocks a large one is split into: a
    // global key's 245 are neither freed nor allocated and cleared again (draw_block clears each).
    std::vector<Bitmap> spare_rasters;
    for (Block& block : m_blocks)
        if (block.segment_count == 0)
            spare_rasters.push_back(std::move(block.raster));
    std::erase_if(m_blocks, [](const Block& block) { return block.segment_count == 0; });
    split_large_blocks(std::move(spare_rasters));
    m_segment_count = m_segment_count - change.removed + change.inserted;
    if (too_many_blocks())
        start_blocks(m_segment_count);
}

std::size_t CurveRaster::block_segments(std::size_t segment_count)
{
    constexpr std::size_t blocks = 64;
    return std::clamp(std::bit_ceil((segment_count + blocks - 1) / blocks), fewest_segments_per_block,
                      most_segments_per_block);
}

// Twice the blocks the curve's size asks for (each a full raster), at half the size or less: drawing
// them all again costs what the edits that split them did, a block each.
bool CurveRaster::too_many_blocks() const
{
    const std::size_t size = block_segments(m_segment_count);
    return m_blocks.size() > 2 * ((m_segment_count + size - 1) / size) && m_block_segments * 2 <= size;
}

// A block of more than two blocks' segments becomes blocks of m_block_segments, the last of up
// to twice as many.
void CurveRaster::split_large_blocks(std::vector<Bitmap> spare_rasters)
{
    const auto large = [this](const Block& block) { return block.segment_count > 2 * m_block_segments; };
    if (std::ranges::none_of(m_blocks, large))
        return;
    m_composed_whole = false;
    std::vector<Block> split;
    for (Block& block : m_blocks) {
        if (large(block))
            block.current = false;
        std::size_t left = block.segment_count;
        while (left > 2 * m_block_segments) {
            const bool spare = !spare_rasters.empty();
            Bitmap raster = spare ? std::move(spare_rasters.back()) : Bitmap();
            if (spare)
                spare_rasters.pop_back();
            // A spare raster holds the pixels of the block it was: all its rows are to be cleared.
            const int dirty_rows = spare ? raster.height() : 0;
            split.push_back(Block{m_block_segments, false, std::move(raster), 0, dirty_rows});
            left -= m_block_segments;
        }
        block.segment_count = left;
        split.push_back(std::move(block));
    }
    m_blocks = std::move(split);
}

void CurveRaster::start_blocks(std::size_t segment_count)
{
    m_composed_whole = false;
    m_block_segments = block_segments(segment_count);
    m_blocks.resize((segment_count + m_block_segments - 1) / m_block_segments);
    for (std::size_t b = 0; b < m_blocks.size(); ++b) {
        m_blocks[b].segment_count = std::min(m_block_segments, segment_count - b * m_block_segments);
        m_blocks[b].current = false;
    }
}

// Blocks are independent: a global change of 10^6 control points draws its 245 on two cores.
std::size_t CurveRaster::draw_stale_blocks(const std::vector<std::pair<std::size_t, std::size_t>>& stale,
                                           const SampledCurve& curve, std::size_t most_work)
{
    std::size_t done = 0;
    std::size_t work = 0;
    std::size_t round = most_work == all_work ? stale.size() : 2;
    while (done < stale.size() && work < most_work) {
        const std::size_t count = std::min(round, stale.size() - done);
        std::array<std::size_t, 2> halves{};
        // A thread is worth some 4096 segments (a block of a long path's; many small ones).
        split_across_cores(count, most_segments_per_block / m_block_segments, [&](std::size_t first, std::size_t end) {
            std::size_t half = 0;
            for (std::size_t i = done + first; i < done + end; ++i)
                half += draw_block(m_blocks[stale[i].first], curve, stale[i].second);
            halves[first == 0 ? 0 : 1] = half;
        });
        done += count;
        work += halves[0] + halves[1];
        m_work_done += halves[0] + halves[1];
        // As many blocks as the work left allows at the cost of those drawn, two at the least.
        round = std::max<std::size_t>(2, work == 0 || work >= most_work ? 2 * round : (most_work - work) * done / work);
    }
    return done;
}

void CurveRaster::update(const SampledCurve& curve, const ViewTransform& view, PixelRect clip, std::size_t most_work,
                         SegmentRange unmade)
{
    const std::size_t segment_count = curve.segments.size();
    if (m_view != view || m_clip != clip || m_segment_count != segment_count ||
        m_samples_per_segment != curve.samples_per_segment || (m_blocks.empty() && segment_count > 0)) {
        start_blocks(segment_count);
        m_view = view;
        m_clip = clip;
        m_segment_count = segment_count;
        m_samples_per_segment = curve.samples_per_segment;
    }
    std::vector<std::pair<std::size_t, std::size_t>> stale; // block, its first segment
    bool waiting = false;                                   // for segments to be made
    std::size_t first_segment = 0;
    for (std::size_t b = 0; b < m_blocks.size(); first_segment += m_blocks[b].segment_count, ++b) {
        if (m_blocks[b].current)
            continue;
        if (unmade.meets(first_segment, first_segment + m_blocks[b].segment_count))
            waiting = true;
        else
            stale.push_back({b, first_segment});
    }
    if (stale.empty() && !m_blocks.empty()) {
        // The picture shows no stale block's old pixels.
        if (waiting && !m_composed_whole)
            compose();
        else if (waiting)
            compose_stale_rows();
        return;
    }
    const std::size_t done = draw_stale_blocks(stale, curve, most_work);
    // Blocks drawn on top of a picture of current blocks only are laid over it (a picture drawn
    // in steps); else all are laid again.
    if (!m_composed_whole)
        return compose();
    // The stale rows are laid from every current block, those drawn now included; their other rows
    // are laid over the picture.
    const auto [laid_first, laid_end] = m_stale_rows;
    compose_stale_rows();
    for (std::size_t i = 0; i < done; ++i) {
        const Block& block = m_blocks[stale[i].first];
        if (laid_first >= laid_end) {
            m_composed.merge(block.raster, block.first_row, block.end_row);
            continue;
        }
        m_composed.merge(block.raster, block.first_row, std::min(block.end_row, laid_first));
        m_composed.merge(block.raster, std::max(block.first_row, laid_end), block.end_row);
    }
}

std::size_t CurveRaster::draw_block(Block& block, const SampledCurve& curve, std::size_t first_segment) const
{
    std::size_t lines = 0;
    // Only the rows its lines reached hold pixels (a spare raster's all): a line a key, not a screen.
    block.raster.clear_rows(block.first_row, block.end_row);
    block.first_row = block.raster.height();
    block.end_row = 0;
    Painter painter(block.raster, m_clip);
    const PixelRect box = painter.bounds();
    // Solid lines: the phase only says whether a line's first pixel is the last one's end.
    int phase = first_segment > 0 ? 1 : 0;
    for_each_curve_line(curve, *m_view, first_segment, first_segment + block.segment_count,
                        [&](const PixelLine& line) {
                            if (box.contains(line.from) && box.contains(line.to))
                                light_solid_line(block.raster, line, box, phase);
                            else
                                painter.styled_line(line.from, line.to, LineStyle::solid, phase);
                            ++lines;
                            block.first_row = std::min({block.first_row, line.from.y, line.to.y});
                            block.end_row = std::max({block.end_row, line.from.y + 1, line.to.y + 1});
                        });
    block.current = true;
    return lines + block.segment_count;
}

std::size_t CurveRaster::blocks_drawn() const
{
    return static_cast<std::size_t>(std::ranges::count_if(m_blocks, [](const Block& block) { return block.current; }));
}

// A long trajectory's blocks each reach a few rows: only those are laid.
void CurveRaster::compose()
{
    m_composed.clear();
    for (const Block& block : m_blocks)
        if (block.current)
            m_composed.merge(block.raster, block.first_row, block.end_row);
    m_composed_whole = true;
    m_stale_rows = {0, 0};
}

void CurveRaster::compose_stale_rows()
{
    const auto [first, end] = std::exchange(m_stale_rows, {0, 0});
    if (first >= end)
        return;
    // The first current block's rows are copied (a current block's raster is blank outside the
    // rows it reached), the others laid over them: a path of one block costs one pass, not two.
    bool copied = false;
    for (const Block& block : m_blocks) {
        if (!block.current)
            continue;
        if (!copied)
            m_composed.copy_rows(block.raster, first, end);
        else
            m_composed.merge(block.raster, std::max(first, block.first_row), std::min(end, block.end_row));
        copied = true;
    }
    if (!copied)
        m_composed.clear_rows(first, end);
}

void CurveRaster::add_stale_rows(const Block& block)
{
    if (block.first_row >= block.end_row)
        return;
    if (m_stale_rows.first >= m_stale_rows.second)
        m_stale_rows = {block.first_row, block.end_row};
    else
        m_stale_rows = {std::min(m_stale_rows.first, block.first_row), std::max(m_stale_rows.second, block.end_row)};
}

} // namespace apcs
