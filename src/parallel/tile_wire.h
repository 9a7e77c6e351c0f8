// flowsurf — the tile protocol's messages (screen_tiles.h), laid out once for the end that
// writes them and the end that reads them. Every message is a plain byte string read in
// order; a rectangle is four int32 (x0, y0, x1, y1); pixels go in row order (rows bottom-up).
//   piece    distribute, a piece to a tile's owner: its rectangle r (the tile plus guard
//            where the piece covers it), the piece's depth at every pixel of r (float), then
//            each layer's values at the pixels of r the piece covers (depth < 1), layer
//            after layer, each pixel in the layer's format.
//   history  pull, the maker of a history texture to a process that reads it: the rectangle
//            r, then the texture's texels over r.
//   return   returnValues, a tile's owner to a piece: the values (float) at the pixels of the
//            piece's rectangle within the tile that the piece covers; no rectangle, both ends
//            know it from the piece's message.
#pragma once

#include "core/errors.h"
#include "gl/objects.h"
#include "parallel/pixel_rect.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace flowsurf::methods::tile_wire {

// A pixel's bytes as the texture stores them and the messages carry them (floats, halves,
// or depth as float).
struct PixelFormat {
    GLenum format, type;
    size_t bytes;
    bool depth;
};

inline PixelFormat pixelFormatOf(GLenum internalFormat) {
    switch (internalFormat) {
        case GL_DEPTH_COMPONENT32F: return {GL_DEPTH_COMPONENT, GL_FLOAT, 4, true};
        case GL_R32F: return {GL_RED, GL_FLOAT, 4, false};
        case GL_RG32F: return {GL_RG, GL_FLOAT, 8, false};
        case GL_RGBA32F: return {GL_RGBA, GL_FLOAT, 16, false};
        case GL_R16F: return {GL_RED, GL_HALF_FLOAT, 2, false};
        case GL_RG16F: return {GL_RG, GL_HALF_FLOAT, 4, false};
        case GL_RGBA16F: return {GL_RGBA, GL_HALF_FLOAT, 8, false};
        default:
            throw GlError("screen tiles: texture format " + std::to_string(internalFormat) +
                          " cannot be exchanged (float, half or depth formats only)");
    }
}

inline constexpr size_t kRectBytes = 4 * sizeof(int32_t);
inline constexpr size_t kDepthBytes = sizeof(float);
inline constexpr size_t kReturnBytes = sizeof(float);

// The sizes of the three messages: `covered` pixels of r the piece covers, `layerBytes` the
// bytes of one pixel of every layer together, `texelBytes` one texel of the history texture.
inline size_t pieceBytes(const PixelRect& r, size_t covered, size_t layerBytes) {
    return kRectBytes + r.area() * kDepthBytes + covered * layerBytes;
}
inline size_t historyBytes(const PixelRect& r, size_t texelBytes) { return kRectBytes + r.area() * texelBytes; }
inline size_t returnBytes(size_t covered) { return covered * kReturnBytes; }

// Writes r at `at`; returns where the message goes on.
inline uint8_t* putRect(uint8_t* at, const PixelRect& r) {
    const int32_t v[4] = {r.x0, r.y0, r.x1, r.y1};
    std::memcpy(at, v, kRectBytes);
    return at + kRectBytes;
}

// Reads a message in order; a message shorter than its layout says is an error.
struct Reader {
    const std::vector<uint8_t>& in;
    size_t at = 0;
    const uint8_t* take(size_t n) {
        if (at + n > in.size()) throw GlError("screen tiles: a message from another process is truncated");
        const uint8_t* p = in.data() + at;
        at += n;
        return p;
    }
    PixelRect rect() {
        int32_t v[4];
        std::memcpy(v, take(kRectBytes), kRectBytes);
        return {v[0], v[1], v[2], v[3]};
    }
    bool atEnd() const { return at == in.size(); }
};

}  // namespace flowsurf::methods::tile_wire
