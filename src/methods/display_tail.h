// flowsurf — the display tail every method ends its frame with: its flow texture (F_a or I)
// through contrast enhancement [doc/contrast.md] (the texture's stretch, then the colour's
// lightness histogram) into the overlay [L eq. 10] with its layers, the dye and the legend,
// over the surface's buffers. Display only: nothing here feeds back into the advection.
// Inputs: the flow texture (R32F), the surface's depth, shade and mask (overlay.h) -> the
// composite (RGBA8).
#pragma once

#include "methods/frame.h"
#include "methods/image_work.h"
#include "present/contrast_stretch.h"
#include "present/overlay.h"

namespace flowsurf::methods {

class DisplayTail {
public:
    // `work`: where the method's image stages run (its renderer's, which outlives this).
    DisplayTail(const CommonParams& params, const core::Viewport& viewport, const ImageWork& work);
    // True when the texture's contrast is enhanced: a tiled render then measures its range on
    // the tiles (measureTile) before the frame's show.
    bool enhancesTexture() const { return contrast_.enabled(); }
    // Tiled, collective: the texture's contrast histogram of this process's tile (`depth`: the
    // whole surface's there), summed over the group. Nothing when not enhanced or not tiled.
    void measureTile(const gl::Texture2D& flow, const gl::Texture2D& depth, gl::StageTimer& timer);
    // The frame's tail into `target` (the composite as colour attachment 0). From `in`: the
    // dye layer and the surface the legend layer names; tiled: only the pixels of this piece
    // are written, with the range measured on the tiles.
    void show(const FrameInput& in, const gl::Texture2D& flow, const SurfaceImage& surface,
              const gl::Framebuffer& target, gl::StageTimer& timer);
    // What the last show displayed of `flow`: its stretch when the texture is enhanced.
    const gl::Texture2D& shown(const gl::Texture2D& flow) const { return stretched_ ? *stretched_ : flow; }

private:
    const ImageWork& work_;
    Overlay overlay_;
    ContrastStretch contrast_;
    const gl::Texture2D* stretched_ = nullptr;  // the contrast stretch shown last, if any
};

}  // namespace flowsurf::methods
