#include "methods/display_tail.h"

#include "methods/stages.h"

namespace flowsurf::methods {

DisplayTail::DisplayTail(const CommonParams& params, const core::Viewport& viewport, const ImageWork& work)
    : work_(work), overlay_(params), contrast_(params, viewport) {}

void DisplayTail::measureTile(const gl::Texture2D& flow, const gl::Texture2D& depth, gl::StageTimer& timer) {
    if (!contrast_.enabled() || !work_.tiled()) return;
    timer.begin(stageName(Stage::ContrastTexture));
    contrast_.measure(flow, depth, work_.tile(), work_.group());
}

void DisplayTail::show(const FrameInput& in, const gl::Texture2D& flow, const SurfaceImage& surface,
                       const gl::Framebuffer& target, gl::StageTimer& timer) {
    // Contrast enhancement of the texture: stretched between its robust percentiles, over the
    // whole image here or over the tiles' summed histograms (measureTile).
    if (contrast_.enabled()) timer.begin(stageName(Stage::ContrastTexture));
    if (!work_.tiled()) contrast_.measure(flow, surface.depth);
    const gl::Texture2D& shown = contrast_.stretch(flow, surface.depth);
    stretched_ = &shown == &flow ? nullptr : &shown;
    // ... and of the colour: the lightness histogram the overlay stretches by
    if (overlay_.stretchesColor()) {
        timer.begin(stageName(Stage::ContrastColour));
        overlay_.measureLightness(shown, surface);
    }

    // The overlay [L eq. 10] with the dye and legend layers
    timer.begin(stageName(Stage::Overlay));
    overlay_.apply(shown, surface, target, *in.surface, in.dye, work_.piecePixels(*in.surface, in.camera));
}

}  // namespace flowsurf::methods
