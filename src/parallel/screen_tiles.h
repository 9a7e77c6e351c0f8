// flowsurf — sort-last parallel rendering with the image stages divided over the processes
// by screen tiles (CommonParams::parallel = tiles; process_group.h's mergeByDepth is the
// replicated reference). Each process renders its piece of the surface into its per-pixel
// buffers as at one process; then, per dynamic frame:
//   split   every process's coverage (16 x 16-pixel cells, summed over the group) is cut
//           into one rectangle per process by weighted recursive bisection, the same on
//           every process (no broadcast): the tile where that process runs the image stages;
//   gather  every process sends each tile's owner its buffers over the tile plus a guard
//           band (what the stages read around the tile: the method's own reach), and the
//           owner merges them by depth, the nearest fragment winning (on a tie the lowest
//           rank), so its buffers over the tile and guard equal the one-process buffers;
// and every frame:
//   return  the owner sends the image stage's result (R32F: the hybrid's I, ISA's and IBFVS's
//           F_a) at each pixel of its tile back
//           to every process whose piece covers that pixel, which overlays and composites
//           its own fragments with its own shade, mask and depth; the host's depth
//           compositing (ParaView's IceT) keeps the nearest, as for any surface.
// and for ISA and IBFVS, whose F_a is next frame's input, read at the advected coordinates:
//   pull    each frame a process obtains from the owners of the split that made the source
//           F_a exactly the rectangle its pixels read (its footprint), before advecting
//           (ISA also the merged depth its edge test reads there).
// The result at every pixel equals the one-process image as long as the stages read no
// further than the guard (the methods derive it from their parameters).
// The idea of screen-space decomposition with guard pixels for a parallel surface LIC is
// Loring, Karimabadi & Bethel (LBNL 2014); the weighted split and the return of every
// value to the process whose fragment won are flowsurf's.
// Cost per dynamic frame and process: one read-back of depth (4 B/px) over the piece's
// footprint, and of the layers over the box of what it sends and of where it is merged; messages of 4 B per pixel of tile plus guard and the
// layers' bytes per covered pixel; the merge on the host over the box of what the others
// sent (this piece's own layers copied on the GPU unless merged in place; the whole tile
// plus guard for a layer whose own values cannot stand for the background); per frame 4 B per covered pixel back,
// the footprint's 4 B per pixel outside the tile, and two floats per process (the measured costs).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "parallel/process_group.h"
#include "parallel/screen_split.h"
#include "parallel/tile_traffic.h"
#include "parallel/tile_wire.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace flowsurf::methods {

// One of the per-pixel buffers an image stage reads: this process's own render (`local`)
// and the texture of the same size and format the tile's merge goes into (`tile`; it may
// be `local` itself: merged in place, which saves a copy over the region and a texture,
// where nothing reads this piece's own values after the merge; written() says where its
// own values were replaced): 2D textures, or one layer of two 3D textures (the hybrid's
// time levels). Formats: float or half with 1-4 channels, or DEPTH32F. `fill`: every channel
// off the surface (a depth layer's is 1). `ownBackground`: off this piece's fragments its
// `local` may stand for the merge there: it holds `fill` (cleared where nothing is drawn) or
// no stage reads the layer off the surface. When every layer says so (the depth layer
// always does), the merge copies this piece's layers on the GPU and merges on the host only
// where other processes sent pixels.
struct TileLayer {
    GLuint local = 0, tile = 0;
    GLenum format = 0;
    int layer = -1;  // the z of 3D textures; -1: 2D textures
    float fill = 0.0f;
    bool ownBackground = false;
    static TileLayer of(const gl::Texture2D& local, const gl::Texture2D& tile, float fill = 0.0f,
                        bool ownBackground = false);
    static TileLayer ofLayer(GLuint local3d, GLuint tile3d, GLenum format, int z);
};

class ScreenTiles {
public:
    static constexpr int kCellPx = 16;

    explicit ScreenTiles(const core::Viewport& viewport);

    // Collective, on a dynamic frame, after every process rendered its piece into `depth`
    // (DEPTH32F) and the layers' `local` textures: splits the screen and fills every
    // layer's `tile` over this process's tile plus `guardPx` (region()) with the whole
    // surface's buffers there, merged by depth (zero off the surface). The depth layer, if
    // one is wanted merged, is a layer like the others (its background 1). `footprint`: where
    // this piece can have drawn (SurfaceGBuffer::footprint); `depth` is 1 outside it.
    void distribute(ProcessGroup& group, const gl::Texture2D& depth, std::span<const TileLayer> layers, int guardPx,
                    const PixelRect& footprint);

    // Collective, every frame after the image stage: `values` (R32F, full size) holds the
    // stage's result over this process's tile; afterwards it holds at every pixel that this
    // process's piece covers (its `depth` < 1 in distribute) the value computed there by
    // the tile's owner. Other pixels keep their values.
    void returnValues(ProcessGroup& group, const gl::Texture2D& values);

    // Collective: history from its footprint. Every process states the rectangle of
    // `texture` it will read this frame (`wanted`: where its advected coordinates land);
    // the processes that own parts of it under `madeWith` (the split the texture was made
    // with: tiles() then) send them, and they are written into `texture`; the rest of it is
    // left as it is. Exact as long as `wanted` holds every texel read.
    void pull(ProcessGroup& group, const gl::Texture2D& texture, const std::vector<PixelRect>& madeWith,
              const PixelRect& wanted);

    // Collective, once per frame after the image stages: `ms`, what they took on this
    // process's tile, and `ownMs`, what this process's own piece cost it in the same frame
    // (work no split moves: drawing it). When the slowest process has taken more than
    // kImbalance times the mean for kImbalanceFrames frames in a row, the cells are
    // weighted by the measured costs (costWeights) from then on and each process's share of
    // them is set against its own work (tileShares), and splitDue() says so until the next
    // distribute, which the method then runs at once from its own buffers (history is
    // pulled from the split that made it, so a new split needs nothing more).
    static constexpr float kImbalance = 1.15f;
    static constexpr int kImbalanceFrames = 3;
    void reportCost(ProcessGroup& group, float ms, float ownMs = 0.0f);
    // What GL work issued since `start` took: waits for it (glFinish), then the ms since
    // `start`. The costs reportCost takes.
    using Clock = std::chrono::steady_clock;
    static float finishedMs(Clock::time_point start);
    bool splitDue() const { return splitDue_; }

    // This process's tile (where its image stages run) and the tile plus guard.
    const PixelRect& tile() const { return tiles_[size_t(rank_)]; }
    const PixelRect& region() const { return region_; }
    // Where the last distribute wrote the merge (within region()); a layer merged in place
    // holds other processes' values or its `fill` there.
    const PixelRect& written() const { return written_; }
    const std::vector<PixelRect>& tiles() const { return tiles_; }
    bool ready() const { return !tiles_.empty(); }
    // What this process sent and received since the last beginFrame().
    const TileTraffic& traffic() const { return traffic_; }
    void beginFrame() { traffic_ = {}; }

private:
    using PixelFormat = tile_wire::PixelFormat;
    // What distribute read from the other pieces: where each one's layers' values start
    // ([process][layer]) and its depth, the box of all they sent, and where the merge runs.
    struct Received {
        std::vector<std::vector<const uint8_t*>> values;
        std::vector<const float*> depthOf;
        PixelRect others, merged;
    };
    // distribute's steps, in order.
    static std::vector<PixelFormat> formatsOf(std::span<const TileLayer> layers);
    void readDepth(const gl::Texture2D& depth, const PixelRect& footprint);
    std::vector<float> coverage(const PixelRect& footprint, PixelRect& covered) const;
    void split(ProcessGroup& group, std::vector<float> weight, int guardPx);
    void writePieces(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats,
                     const PixelRect& covered, int guardPx);
    Received readPieces(const std::vector<std::vector<uint8_t>>& in, const std::vector<PixelFormat>& formats);
    void mergeNearest(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats, Received& got,
                      GLuint depth);
    void writeMerge(std::span<const TileLayer> layers, const std::vector<PixelFormat>& formats, const Received& got,
                    const PixelRect& previous);
    void countCovered(const PixelRect& footprint, const PixelRect& merged);
    void copyOwn(std::span<const TileLayer> layers, const PixelRect& region);

    core::Viewport viewport_;
    int rank_ = 0;
    std::vector<PixelRect> tiles_;          // every process's tile
    PixelRect region_;                      // this process's tile plus guard, in the viewport
    PixelRect written_;                     // where the last merge was written
    std::vector<float> depth_;              // this process's own depth (full image, bottom-up)
    // This process's message to tile owner t covered sent_[t] (its coverage there is depth_).
    std::vector<PixelRect> sent_;
    // What process q sent this one: its rectangle and its depth there (the return trip
    // sends q the values where q's depth < 1).
    std::vector<PixelRect> received_;
    std::vector<std::vector<float>> receivedDepth_;
    std::vector<float> values_, tileValues_;  // scratch for returnValues
    // Scratch for distribute, kept between frames (no allocation per frame): this piece's
    // layers over what it sends and over where it takes part in the merge, the messages
    // (returns_: returnValues'; apart, so that neither regrows, zeroed, every frame),
    // the covered pixels of one message, the merge's nearest depth, winning process and its
    // value index per pixel of the region, the merged layers.
    std::vector<std::vector<uint8_t>> local_, own_, sends_, returns_, merged_;
    std::vector<uint32_t> pixelIndex_, winnerAt_;
    std::vector<float> best_;
    std::vector<int32_t> winner_;
    // The last split's cell weights, the measured cost scale per cell, each process's share
    // of them (empty: even), and the balance.
    std::vector<float> weights_, costScale_, shares_;
    int cellsX_ = 0, imbalanced_ = 0;
    bool splitDue_ = false;
    TileTraffic traffic_;
};

}  // namespace flowsurf::methods
