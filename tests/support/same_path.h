#pragma once

#include "apcs/animation/arc_length.h"
#include "apcs/animation/motion_path.h"

#include <catch2/catch.hpp>

#include <cstddef>

namespace apcs::test {

// `kept` (re-evaluated, refined, or evaluated into arrays that kept their room) equals `fresh`
// to the bit: segments (none unmade), lengths, exact spacing's arc lengths (none pending), in-betweens, their
// spans and the frames that freeze.
inline void require_same_path(const EvaluatedPath& kept, const EvaluatedPath& fresh)
{
    REQUIRE(kept.inbetweens_current);
    REQUIRE(kept.segments_unmade.empty());
    REQUIRE(kept.curve.segments == fresh.curve.segments);
    REQUIRE(kept.curve.segment_length == fresh.curve.segment_length);
    REQUIRE(kept.curve.length_to_point == fresh.curve.length_to_point);
    REQUIRE(kept.arc_lengths.segment_count() == fresh.arc_lengths.segment_count());
    REQUIRE_FALSE(kept.arc_lengths.pending());
    for (std::size_t k = 0; k <= fresh.arc_lengths.segment_count(); ++k)
        REQUIRE(kept.arc_lengths.length_to_segment_start(k) == fresh.arc_lengths.length_to_segment_start(k));
    REQUIRE(kept.inbetweens.size() == fresh.inbetweens.size());
    for (std::size_t j = 0; j < fresh.inbetweens.size(); ++j) {
        REQUIRE(kept.inbetweens[j].position == fresh.inbetweens[j].position);
        REQUIRE(kept.inbetweens[j].arc_fraction == fresh.inbetweens[j].arc_fraction);
        REQUIRE(kept.inbetweens[j].sample_index == fresh.inbetweens[j].sample_index);
    }
    REQUIRE(kept.span_timings.size() == fresh.span_timings.size());
    for (std::size_t s = 0; s < fresh.span_timings.size(); ++s) {
        REQUIRE(kept.span_timings[s].span.first_point == fresh.span_timings[s].span.first_point);
        REQUIRE(kept.span_timings[s].span.last_point == fresh.span_timings[s].span.last_point);
        REQUIRE(kept.span_timings[s].span.acceleration == fresh.span_timings[s].span.acceleration);
        REQUIRE(kept.span_timings[s].start_fraction == fresh.span_timings[s].start_fraction);
        REQUIRE(kept.span_timings[s].length_fraction == fresh.span_timings[s].length_fraction);
        REQUIRE(kept.span_timings[s].inbetween_count == fresh.span_timings[s].inbetween_count);
    }
    REQUIRE(kept.frozen_frames == fresh.frozen_frames);
}

} // namespace apcs::test
