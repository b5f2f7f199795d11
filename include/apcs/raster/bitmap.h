#pragma once

#include "apcs/geometry/hercules.h"
#include "apcs/geometry/pixel_point.h"

#include <cstdint>
#include <vector>

namespace apcs {

// A one-bit raster, 720x348 by default like the Hercules screen: 8 pixels a byte, most significant
// bit leftmost, rows top to bottom. Reads outside the raster give 0; writes there are ignored.
class Bitmap {
public:
    Bitmap(int width = hercules::screen_width, int height = hercules::screen_height);

    int width() const { return m_width; }
    int height() const { return m_height; }
    PixelRect bounds() const { return {0, 0, m_width, m_height}; }
    bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < m_width && y < m_height; }

    bool get(int x, int y) const;
    void set(int x, int y, bool lit)
    {
        if (!contains(x, y))
            return;
        // Most significant bit leftmost.
        const auto bit = static_cast<std::uint8_t>(0x80u >> (x & 7));
        std::uint8_t& byte = m_bits[static_cast<std::size_t>(y) * m_bytes_per_row + static_cast<std::size_t>(x >> 3)];
        byte = lit ? static_cast<std::uint8_t>(byte | bit) : static_cast<std::uint8_t>(byte & ~bit);
    }
    void toggle(int x, int y);
    // Lights pixels first_x … last_x (either order) of row y, those on the raster: a byte at a time.
    void set_run(int y, int first_x, int last_x);
    void clear();
    // Rows first_row … end_row − 1 unlit (clamped to the raster).
    void clear_rows(int first_row, int end_row);
    // Rows first_row … end_row − 1 as they are in `other`, a bitmap of the same size (clamped).
    void copy_rows(const Bitmap& other, int first_row, int end_row);
    std::size_t lit_count() const;
    // Lights every pixel lit in `other`, a bitmap of the same size: all of it, or its rows
    // first_row … end_row − 1 (clamped to the raster).
    void merge(const Bitmap& other);
    void merge(const Bitmap& other, int first_row, int end_row);
    bool operator==(const Bitmap&) const = default;

    // Row `y` as packed bytes (width/8 rounded up).
    const std::uint8_t* row(int y) const { return m_bits.data() + static_cast<std::size_t>(y) * m_bytes_per_row; }

private:
    int m_width;
    int m_height;
    std::size_t m_bytes_per_row;
    std::vector<std::uint8_t> m_bits;
};

} // namespace apcs
