// flowsurf — where a method's image stages run, chosen once when the renderer is made from
// its process group and CommonParams::parallel: over the whole image at one process (Whole),
// over the whole image at every process of a group (Replicated, parallel = replicate: the
// per-pixel buffers merged by depth first, process_group.h), or over one screen tile each
// (Tiled, parallel = tiles, screen_tiles.h). A method states its buffers and its stages'
// reach; this runs the step each mode needs (gather: the merge or the distribute; pull,
// cost, return), keeps the split each history texture was made with, the whole surface's
// depth a tile is merged into, and what the frame exchanged. Where a mode has no such step
// it does nothing, and the tile is the whole image.
#pragma once

#include "gl/stage_timer.h"
#include "methods/frame.h"
#include "methods/stages.h"
#include "parallel/process_group.h"
#include "parallel/screen_tiles.h"

#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace flowsurf::methods {

class SurfaceGBuffer;

class ImageWork {
public:
    enum class Mode {
        Whole,       // one process: no group
        Replicated,  // a group of one, or parallel = replicate: every process the whole image
        Tiled,       // a group of several with parallel = tiles: every process its own tile
    };
    // `group`: the processes rendering this view together, each with its own piece of the
    // surface (sort-last, process_group.h), for the renderer's life; null: this process
    // alone. `historySlots`: the textures that carry a method's image from frame to frame
    // (ISA's and IBFVS's two F_a, ISA's depths), each pulled from the split that made it.
    // `depthTargets`: the textures a tile's whole-surface depth is merged into (wholeDepth).
    // Throws ConfigError when `params` ask for what the mode cannot give (the colour's
    // contrast stretch over tiles).
    ImageWork(const core::Viewport& viewport, const CommonParams& params, ProcessGroup* group, int historySlots,
              int depthTargets = 0);
    Mode mode() const { return mode_; }
    bool tiled() const { return mode_ == Mode::Tiled; }
    // The group (null when Whole): the per-frame collectives of stages such as the edge mask.
    ProcessGroup* group() const { return group_; }
    // Tiled: the group whose pieces hide this one's pixels (SurfaceGBuffer::render); null otherwise.
    ProcessGroup* occluders() const { return tiled() ? group_ : nullptr; }
    // At each frame's start: the traffic counts anew.
    void beginFrame();

    // Collective: the whole surface's per-pixel buffers where this process's image stages
    // run, after every process drew its piece. Replicated: `buffers` merged over the whole
    // image (SurfaceGBuffer::merge); Tiled: `tileLayers` over the tile plus `guardPx`
    // (ScreenTiles::distribute from the buffers' depth and footprint, timed as the tile
    // exchange; a merge in place is cleared by their next render where they clear their
    // background); Whole: nothing.
    void gather(SurfaceGBuffer& buffers, std::span<const TileLayer> tileLayers, int guardPx, gl::StageTimer& timer);
    // The same from a method's own buffers: Replicated: `whole` merged over the group by
    // `depth` (nearest fragment); Tiled: `tileLayers` distributed from `depth` drawn within
    // `footprint`.
    void gather(const gl::Texture2D& depth, const PixelRect& footprint,
                std::initializer_list<const gl::Texture2D*> whole, std::span<const TileLayer> tileLayers, int guardPx,
                gl::StageTimer& timer);
    // Where the stages read the whole surface's depth: Tiled, the merge target `i` (a
    // gather's layer fills it over the tile and guard); otherwise `own`, which holds it (the
    // whole image's after a replicated merge, or this process's alone). Also `own` when the
    // method asked for fewer targets.
    const gl::Texture2D& wholeDepth(int i, const gl::Texture2D& own) const;
    // Where this process's image stages run: its tile (maybe empty), or the whole image.
    PixelRect tile() const;
    // The pixels of `tile()` a stage restricted to them writes: none (every pixel) unless
    // tiled.
    std::optional<PixelRect> tileOnly() const;
    // Tiled: the pixels this process's piece can cover (its projected parts): the host shows
    // only those of its images (the other processes' fragments elsewhere), so its overlay
    // writes only those; none otherwise (every pixel).
    std::optional<PixelRect> piecePixels(const SurfaceGpu& surface, const core::Camera& camera) const;
    // Tiled: the measured costs call for a new split, which the next gather makes.
    bool splitDue() const { return tiled() && tiles_->splitDue(); }

    // Tiled, collective: the `wanted` part of history texture `slot` from the processes whose
    // tiles made it, timed as the tile exchange; the timer then goes on with `resume`. False
    // when nothing was pulled (not tiled, or the texture's first frame).
    bool pull(int slot, const gl::Texture2D& texture, const PixelRect& wanted, gl::StageTimer& timer, Stage resume);
    // The clock of an image stage's cost (finished, costSince).
    using Clock = ScreenTiles::Clock;
    // Tiled: what GL work issued since `start` took (waits for it); 0 otherwise (no wait).
    float costSince(Clock::time_point start) const;
    // Tiled, collective, once the image stage begun at `start` ran on the tile: its cost
    // (and `ownMs`: this piece's own work, which no split moves) toward the balance
    // (ScreenTiles::reportCost). Nothing otherwise.
    void finished(Clock::time_point start, float ownMs = 0.0f);
    // Tiled: history texture `slot` was made with this frame's split (its next pull's owners).
    void made(int slot);
    // History texture `to` now holds what `from` held (a copy of it), made by the same split.
    void copied(int from, int to) { madeWith_[size_t(to)] = madeWith_[size_t(from)]; }
    // Tiled, collective: `values` at this piece's own pixels from their tiles' owners
    // (ScreenTiles::returnValues), timed as the tile return. Nothing otherwise.
    void returnValues(const gl::Texture2D& values, gl::StageTimer& timer);
    TileTraffic traffic() const { return tiles_ ? tiles_->traffic() : TileTraffic{}; }

private:
    void distribute(const gl::Texture2D& depth, std::span<const TileLayer> layers, int guardPx,
                    const PixelRect& footprint, gl::StageTimer& timer);

    core::Viewport viewport_;
    ProcessGroup* group_ = nullptr;
    Mode mode_ = Mode::Whole;
    std::unique_ptr<ScreenTiles> tiles_;    // Tiled
    std::vector<gl::Texture2D> wholeDepth_;  // Tiled: the merge targets of the whole surface's depth
    // The split each history texture was made with: its owners, from whom a process pulls.
    std::vector<std::vector<PixelRect>> madeWith_;
};

}  // namespace flowsurf::methods
