#include "apcs/raster/bitmap.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cstring>

namespace apcs {

Bitmap::Bitmap(int width, int height)
    : m_width(std::max(width, 0))
    , m_height(std::max(height, 0))
    , m_bytes_per_row((static_cast<std::size_t>(m_width) + 7) / 8)
    , m_bits(m_bytes_per_row * static_cast<std::size_t>(m_height), 0)
{
}

namespace {
constexpr std::uint8_t bit_of(int x) { return static_cast<std::uint8_t>(0x80u >> (x & 7)); }
} // namespace

bool Bitmap::get(int x, int y) const
{
    if (!contains(x, y))
        return false;
    return (row(y)[x >> 3] & bit_of(x)) != 0;
}

void Bitmap::set_run(int y, int first_x, int last_x)
{
    if (y < 0 || y >= m_height)
        return;
    const int left = std::max(std::min(first_x, last_x), 0);
    const int right = std::min(std::max(first_x, last_x), m_width - 1);
    if (left > right)
        return;
    std::uint8_t* row_bits = m_bits.data() + static_cast<std::size_t>(y) * m_bytes_per_row;
    const int first_byte = left >> 3;
    const int last_byte = right >> 3;
    // Most significant bit leftmost: the bits from x's on, and those up to x's.
    const auto from_bit = [](int x) { return static_cast<std::uint8_t>(0xFFu >> (x & 7)); };
    const auto to_bit = [](int x) { return static_cast<std::uint8_t>(0xFFu << (7 - (x & 7))); };
    if (first_byte == last_byte) {
        row_bits[first_byte] |= static_cast<std::uint8_t>(from_bit(left) & to_bit(right));
        return;
    }
    row_bits[first_byte] |= from_bit(left);
    for (int byte = first_byte + 1; byte < last_byte; ++byte)
        row_bits[byte] = 0xFF;
    row_bits[last_byte] |= to_bit(right);
}

void Bitmap::toggle(int x, int y)
{
    if (!contains(x, y))
        return;
    m_bits[static_cast<std::size_t>(y) * m_bytes_per_row + static_cast<std::size_t>(x >> 3)] ^= bit_of(x);
}

void Bitmap::clear() { std::fill(m_bits.begin(), m_bits.end(), std::uint8_t{0}); }

void Bitmap::clear_rows(int first_row, int end_row)
{
    const auto clamped = [&](int row) { return static_cast<std::ptrdiff_t>(std::clamp(row, 0, m_height)); };
    const auto row_bytes = static_cast<std::ptrdiff_t>(m_bytes_per_row);
    if (clamped(first_row) < clamped(end_row))
        std::fill(m_bits.begin() + clamped(first_row) * row_bytes, m_bits.begin() + clamped(end_row) * row_bytes,
                  std::uint8_t{0});
}

void Bitmap::copy_rows(const Bitmap& other, int first_row, int end_row)
{
    assert(other.m_width == m_width && other.m_height == m_height);
    const auto clamped = [&](int row) { return static_cast<std::ptrdiff_t>(std::clamp(row, 0, m_height)); };
    const auto row_bytes = static_cast<std::ptrdiff_t>(m_bytes_per_row);
    if (clamped(first_row) < clamped(end_row))
        std::copy(other.m_bits.begin() + clamped(first_row) * row_bytes,
                  other.m_bits.begin() + clamped(end_row) * row_bytes, m_bits.begin() + clamped(first_row) * row_bytes);
}

void Bitmap::merge(const Bitmap& other) { merge(other, 0, m_height); }

void Bitmap::merge(const Bitmap& other, int first_row, int end_row)
{
    assert(other.m_width == m_width && other.m_height == m_height);
    const auto clamped = [&](int row) { return static_cast<std::size_t>(std::clamp(row, 0, m_height)); };
    const std::size_t end = clamped(end_row) * m_bytes_per_row;
    std::size_t i = clamped(first_row) * m_bytes_per_row;
    // Eight bytes at a time: the curve's picture lays its blocks over one another at every key.
    for (; i + sizeof(std::uint64_t) <= end; i += sizeof(std::uint64_t)) {
        std::uint64_t word = 0;
        std::uint64_t added = 0;
        std::memcpy(&word, m_bits.data() + i, sizeof word);
        std::memcpy(&added, other.m_bits.data() + i, sizeof added);
        word |= added;
        std::memcpy(m_bits.data() + i, &word, sizeof word);
    }
    for (; i < end; ++i)
        m_bits[i] |= other.m_bits[i];
}

std::size_t Bitmap::lit_count() const
{
    std::size_t count = 0;
    for (const std::uint8_t byte : m_bits)
        count += static_cast<std::size_t>(std::popcount(byte));
    return count;
}

} // namespace apcs
