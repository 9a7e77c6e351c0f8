// flowsurf — a rectangle of pixels: a tile, a piece's footprint, what a pass writes.
#pragma once

#include <algorithm>
#include <cstddef>

namespace flowsurf::methods {

// A pixel rectangle [x0, x1) x [y0, y1) in GL's image coordinates (rows bottom-up).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return std::max(0, x1 - x0); }
    int height() const { return std::max(0, y1 - y0); }
    bool empty() const { return width() == 0 || height() == 0; }
    size_t area() const { return size_t(width()) * size_t(height()); }
    PixelRect intersect(const PixelRect& o) const {
        return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
    }
    PixelRect grown(int g) const { return {x0 - g, y0 - g, x1 + g, y1 + g}; }
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    // The least rectangle holding both; an empty one adds nothing.
    PixelRect united(const PixelRect& o) const {
        if (empty()) return o;
        if (o.empty()) return *this;
        return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
    }
    bool operator==(const PixelRect&) const = default;
};

}  // namespace flowsurf::methods
