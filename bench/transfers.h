// flowsurf — the host transfers that the tiled parallel mode (parallel/screen_tiles.h)
// adds to a frame, timed alone on this machine's GL driver: reading a per-pixel layer back
// (glGetTextureSubImage, as distribute/returnValues/pull do) and uploading one
// (glTextureSubImage2D, as the merge into a tile does). With the frame time of `flowsurf
// bench` they bound how small a frame can be before dividing it over ranks stops paying
// (doc/bench/, the strong-scaling model in docs/parallel.md). Not a test: timings only.
#pragma once

#include "core/camera.h"

#include <vector>

namespace flowsurf::bench {

// Per image size and layer format (RGBA32F: velocity, DEPTH32F: depth, R32F: the returned
// value), the median of `repeats` full-image read-backs and uploads, printed as ms and GB/s.
// Needs a current GL context.
void runTransfers(const std::vector<core::Viewport>& sizes, int repeats);

}  // namespace flowsurf::bench
