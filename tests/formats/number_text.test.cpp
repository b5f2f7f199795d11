#include "apcs/formats/number_text.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

using namespace apcs;

namespace {

std::string fixed(double value, int decimals)
{
    std::string text;
    append_fixed(text, value, decimals);
    return text;
}

} // namespace

TEST_CASE("decimals for a drawing's size keep 0.5e-9 of the size: 9 - floor(log10 size)", "[formats][numbers]")
{
    CHECK(decimals_for_size(1.0) == 9);
    CHECK(decimals_for_size(4.0) == 9);
    CHECK(decimals_for_size(10.0) == 8);
    CHECK(decimals_for_size(9.99) == 9);
    CHECK(decimals_for_size(250.0) == 7);
    CHECK(decimals_for_size(0.05) == 11);
    CHECK(decimals_for_size(1e9) == 0);
    CHECK(decimals_for_size(3e15) == 0);
    CHECK(decimals_for_size(0.0) == 9);
    CHECK(decimals_for_size(1e-9) == 18);
    CHECK(decimals_for_size(9e-10) == -1); // no fixed count is fine enough: the shortest form
}

TEST_CASE("fixed decimals are printf's, never -0, and the shortest form where the digits would not fit",
          "[formats][numbers]")
{
    CHECK(fixed(2.0, 9) == "2.000000000");
    CHECK(fixed(-1.5, 3) == "-1.500");
    CHECK(fixed(0.125, 2) == "0.13"); // half away from zero, as 0.125 is exact
    CHECK(fixed(-0.0001, 3) == "0.000");
    CHECK(fixed(-0.0, 9) == "0.000000000");
    CHECK(fixed(123456.0, 0) == "123456");
    CHECK(fixed(7.0, 1) == "7.0");
    // 0.05 · 10^18 rounds to 5e16 in binary: digits past the double's precision are not invented
    // (printf would show 0.050000000000000003, the binary value's 18th decimal).
    CHECK(fixed(0.05, 18) == "0.050000000000000000");
    CHECK(fixed(1e300, 9) == "1e+300");
    CHECK(fixed(0.1, -1) == "0.1");
    CHECK(fixed(std::nan(""), 4) == "nan");
}

TEST_CASE("fixed decimals read back within half a unit of the last decimal, and agree with printf",
          "[formats][numbers]")
{
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::size_t differ_from_printf = 0;
    for (int i = 0; i < 100000; ++i) {
        const double size = std::pow(10.0, static_cast<double>(i % 13 - 4)) * 7.3;
        const double value = mantissa(random) * size;
        const int decimals = decimals_for_size(size);
        const std::string text = fixed(value, decimals);
        CAPTURE(value, decimals, text);
        REQUIRE(std::abs(std::stod(text) - value) <= 0.5e-9 * size);
        char printed[64];
        std::snprintf(printed, sizeof printed, "%.*f", decimals, value);
        // printf rounds the exact binary value; the fixed writer rounds value × 10^d, so a value
        // within a rounding error of a half may go the other way: rare, and within the bound above.
        differ_from_printf += text != printed && std::string("-") + text != printed ? 1u : 0u;
    }
    CHECK(differ_from_printf < 100);
}
