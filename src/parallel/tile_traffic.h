// flowsurf — what a tiled parallel render exchanged (ScreenTiles, FlowMethod::tileTraffic).
#pragma once

#include <cstddef>

namespace flowsurf::methods {

// What the tiles cost this process in the last frame (FLOWSURF_RANK_STATS).
struct TileTraffic {
    size_t bytesSent = 0, bytesReceived = 0;
    size_t tilePixels = 0, coveredPixels = 0, guardPixels = 0;
};

}  // namespace flowsurf::methods
