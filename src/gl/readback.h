// flowsurf — reading textures back to the CPU (final output and tests only: the
// per-frame pipeline never reads back).
#pragma once

#include "gl/objects.h"

#include <cstdint>
#include <vector>

namespace flowsurf::gl {

// One channel as float, rows bottom to top (GL order). `channel` 0..3.
std::vector<float> readChannel(const Texture2D& texture, int channel = 0);
// RGBA float, rows bottom to top.
std::vector<float> readRgbaFloat(const Texture2D& texture);
// RGB8 rows top to bottom (for PNG and video), from an RGBA8 texture.
std::vector<uint8_t> readRgb8TopDown(const Texture2D& texture);
// 16-bit gray rows top to bottom from channel 0, values clamped to [0,1].
std::vector<uint16_t> readGray16TopDown(const Texture2D& texture);
// Depth texture as float, rows bottom to top.
std::vector<float> readDepth(const Texture2D& texture);

}  // namespace flowsurf::gl
