// flowsurf — reading textures back to the CPU: final output, tests, and the parallel
// modes' exchanges (screen_tiles.h, process_group.h).
#pragma once

#include "gl/objects.h"

#include <cstdint>
#include <vector>

namespace flowsurf::gl {

// Waits until every GL command issued so far has run. Every texture read-back calls it
// first: under CPU load llvmpipe (Mesa 22.3) handed the tile exchange the hybrid's seeds
// partly undrawn (one 64 x 64 bin up to its 40th row; the hybrid draws its time levels into
// another framebuffer between the seeds and their read-back), which this wait prevents
// (TiledParallelUnsteady). A read waits for its data anyway; this adds only the wait for
// the commands issued after that data's pass.
void waitForRendering();

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
