// flowsurf — where a method's image stages run: over the whole image at one process, over
// the whole image at every process of a group (parallel = replicate: the per-pixel buffers
// merged by depth first, process_group.h), or over one screen tile each (parallel = tiles,
// screen_tiles.h). A method states its buffers and its stages' reach; this owns the tiles
// protocol's steps (distribute, pull, cost, return), the split each history texture was made
// with, and what the frame exchanged. At one process and in the replicate mode every tiles
// step does nothing and the tile is the whole image.
#pragma once

#include "gl/stage_timer.h"
#include "methods/frame.h"
#include "methods/stages.h"
#include "parallel/process_group.h"
#include "parallel/screen_tiles.h"

#include <initializer_list>
#include <memory>
#include <span>
#include <vector>

namespace flowsurf::methods {

class ImageWork {
public:
    // `historySlots`: the textures that carry a method's image from frame to frame (ISA's and
    // IBFVS's two F_a, ISA's depths), each pulled from the split that made it.
    ImageWork(const core::Viewport& viewport, const CommonParams& params, int historySlots);
    // At each frame's start: this frame's group (FrameInput::group); the traffic counts anew.
    void beginFrame(const FrameInput& in);
    bool tiled() const { return tiled_; }
    // The group when its processes each hold the whole image (replicate), or when they
    // divide it into tiles; null otherwise.
    ProcessGroup* replicated() const { return tiled_ ? nullptr : group_; }
    ProcessGroup* tiledGroup() const { return tiled_ ? group_ : nullptr; }
    // Replicate mode: `layers` merged over the group by `depth` (nearest fragment), so every
    // process holds the whole surface's buffers. Nothing at one process or with tiles.
    void mergeReplicated(const gl::Texture2D& depth, std::initializer_list<const gl::Texture2D*> layers) const;
    // Tiles, collective: the whole surface's `layers` over this process's tile plus
    // `guardPx` (ScreenTiles::distribute), timed as the tile exchange.
    void distribute(const gl::Texture2D& depth, std::span<const TileLayer> layers, int guardPx,
                    const PixelRect& footprint, gl::StageTimer& timer);
    // Where this process's image stages run: its tile (maybe empty), or the whole image.
    PixelRect tile() const;
    // Tiles: where the last distribute wrote the merge (ScreenTiles::written).
    PixelRect written() const { return tiles_->written(); }
    // Tiles: the measured costs call for a new split, which the next distribute makes.
    bool splitDue() const { return tiled_ && tiles_->splitDue(); }
    // Tiles, collective: the `wanted` part of history texture `slot` from the processes whose
    // tiles made it, timed as the tile exchange; the timer then goes on with `resume`. False
    // when nothing was pulled (not tiled, or the texture's first frame).
    bool pull(int slot, const gl::Texture2D& texture, const PixelRect& wanted, gl::StageTimer& timer, Stage resume);
    // Tiles, collective, once the image stage ran on the tile: its cost `ms` (and `ownMs`:
    // this piece's own work, which no split moves) toward the balance (ScreenTiles::reportCost).
    void reportCost(float ms, float ownMs = 0.0f);
    // Tiles: history texture `slot` was made with this frame's split (its next pull's owners).
    void made(int slot);
    // History texture `to` now holds what `from` held (a copy of it), made by the same split.
    void copied(int from, int to) { madeWith_[size_t(to)] = madeWith_[size_t(from)]; }
    // Tiles, collective: `values` at this piece's own pixels from their tiles' owners
    // (ScreenTiles::returnValues), timed as the tile return.
    void returnValues(const gl::Texture2D& values, gl::StageTimer& timer);
    TileTraffic traffic() const { return tiles_ ? tiles_->traffic() : TileTraffic{}; }

private:
    core::Viewport viewport_;
    ParallelMode mode_;
    ProcessGroup* group_ = nullptr;  // this frame's
    bool tiled_ = false;
    std::unique_ptr<ScreenTiles> tiles_;  // made on the first tiled frame
    // The split each history texture was made with: its owners, from whom a process pulls.
    std::vector<std::vector<PixelRect>> madeWith_;
};

}  // namespace flowsurf::methods
