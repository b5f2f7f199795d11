#include "apcs/animation/memory_budget.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace apcs;

TEST_CASE("a path needs (segments x samples + 1) curve samples, its in-betweens and its control points",
          "[animation][memory]")
{
    // Samples are computed, not held: 12 in-betweens x 48 and 3 control points x 320, whatever
    // the samples.
    CHECK(memory::path_bytes({3, 1000, 12, false}) == 12 * 48 + 3 * 320);
    CHECK(memory::path_bytes({3, 100000, 12, false}) == 1536);
    // Printed, each of the 2 x 1000 + 1 samples is held (24) and each sample and in-between is a
    // line of text of up to 60 bytes.
    CHECK(memory::path_bytes({3, 1000, 12, true}) == 2001 * 84 + 12 * 108 + 3 * 320);
    CHECK(memory::path_bytes({3, 1000, 12, true}) == 170340);
    // Ten times the samples printed, about ten times the memory: 20001 x 84 + 1296 + 960.
    CHECK(memory::path_bytes({3, 10000, 12, true}) == 1682340);
    // The case: 1,000 control points x 100000 samples, printed.
    CHECK(memory::path_bytes({1000, 100000, 12, true}) == 99'900'001ull * 84 + 12 * 108 + 1000 * 320);
}

TEST_CASE("frames need frames x points x 24 bytes and each key point's own share", "[animation][memory]")
{
    // 1002 x 4 x 24 + 4 x (8 x 60 + 128).
    CHECK(memory::frames_bytes({1002, 4, false}) == 96192 + 2432);
    CHECK(memory::frames_bytes({1002, 4, true}) == 1002 * 4 * 84 + 2432);
    // 10^6-point keys with 100000 in-betweens: 2.4 TB of frames.
    CHECK(memory::frames_bytes({100002, 1'000'000, false}) == 2'400'048'000'000ull + 608'000'000ull);
}

TEST_CASE("byte counts saturate instead of wrapping", "[animation][memory]")
{
    const std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
    CHECK(memory::frames_bytes({std::numeric_limits<std::size_t>::max(), 2, false}) == most);
    CHECK(memory::saturating_sum(most - 1, 5) == most);
}

TEST_CASE("APCS_MEMORY_LIMIT takes bytes or K, M, G, T in powers of 1024", "[animation][memory]")
{
    CHECK(memory::parse_byte_count("4294967296") == 4294967296ull);
    CHECK(memory::parse_byte_count("512K") == 512ull * 1024);
    CHECK(memory::parse_byte_count("64m") == 64ull << 20);
    CHECK(memory::parse_byte_count("4G") == 4ull << 30);
    CHECK(memory::parse_byte_count("4GiB") == 4ull << 30);
    CHECK(memory::parse_byte_count("2tb") == 2ull << 40);
    for (const char* bad : {"", "0", "G", "4X", "4 G", "-1", "4GG", "99999999999999999999", "16777216T"})
        CHECK_FALSE(memory::parse_byte_count(bad));
}

TEST_CASE("byte counts are shown in the unit that keeps them below 1024", "[animation][memory]")
{
    CHECK(memory::byte_count_text(900) == "900 bytes");
    CHECK(memory::byte_count_text(4ull << 30) == "4 GiB");
    CHECK(memory::byte_count_text(234372) == "228.9 KiB");
    CHECK(memory::byte_count_text(3ull << 19) == "1.5 MiB");
}

TEST_CASE("a request over the limit is refused with what it needs and the limit", "[animation][memory]")
{
    CHECK(memory::check_fits("x", 1024, 1024, "lower y"));
    const Expected<void> refused = memory::check_fits("100 frames of 2 points", 2048, 1024, "lower --inbetweens");
    REQUIRE_FALSE(refused);
    CHECK(refused.error().to_string() == "apcs: 100 frames of 2 points need 2 KiB; the memory limit is 1 KiB "
                                         "(APCS_MEMORY_LIMIT); lower --inbetweens");
}
