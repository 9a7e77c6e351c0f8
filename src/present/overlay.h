// flowsurf — overlay, [L] eq. 10, with texture clipping ([L] Fig. 10), the texture mask
// (velocity or any scalar), the colour legend and contrast enhancement's lightness stretch
// [doc/contrast.md]. Inputs: F_a or its stretch (R32F), depth, shade (RGBA16F: eye normal, colour
// value), mask (R16F). Output: RGBA8. Applied after advection every frame and never fed
// back. A full-screen fragment pass or a compute pass (CommonParams::glPath): the same image.
#pragma once

#include "dye/dye.h"
#include "gl/objects.h"
#include "parallel/pixel_rect.h"
#include "params/params.h"
#include "present/legend_layer.h"
#include "present/percentile_range.h"
#include "raster/surface_gpu.h"

#include <optional>
#include <string>

namespace flowsurf::methods {

// The surface's per-pixel buffers the overlay reads: window depth (1 = background), shade
// (RGBA16F: eye normal, colour value) and the texture mask (R16F).
struct SurfaceImage {
    const gl::Texture2D& depth;
    const gl::Texture2D& shade;
    const gl::Texture2D& mask;
};

class Overlay {
public:
    explicit Overlay(const CommonParams& params);
    // `surface` gives the colour range and name the legend shows. `target`: the composite
    // (RGBA8) as the colour attachment 0 of a framebuffer. `dye`: the dye to show over the
    // surface (FrameInput::dye), or null. `pixels`: the pixels to write (a tiled parallel
    // render writes its own piece's only: the host composites the rest from the others);
    // none: every pixel.
    void apply(const gl::Texture2D& flow, const SurfaceImage& image, const gl::Framebuffer& target,
               const SurfaceGpu& surface, const DyeView* dye = nullptr,
               const std::optional<PixelRect>& pixels = std::nullopt) const;
    // Contrast enhancement of the colour [doc/contrast.md]: the histogram of the surface colour's
    // lightness with these inputs (apply's), whose smoothed percentiles the next apply
    // stretches to [0, 1]. Nothing unless CommonParams::enhanceContrast includes colour.
    // Cost: a pass as the overlay's without writing the image, a 2 KiB read-back.
    void measureLightness(const gl::Texture2D& flow, const SurfaceImage& image) const;
    bool stretchesColor() const { return bool(lightnessProgram_); }

private:
    void bindInputs(const gl::Program& prog, const gl::Texture2D& flow, const SurfaceImage& image) const;

    CommonParams params_;
    GlPath path_;
    gl::Program program_;               // without dye
    mutable gl::Program dyeProgram_;    // with dye, made when a frame first has some
    gl::Program lightnessProgram_;      // contrast enhancement of the colour: its histogram
    mutable PercentileRange lightness_;
    gl::Texture2D colormap_;
    gl::VertexArray emptyVao_;
    // The layers over the surface: the dye (a frame's DyeView, bound by apply) and the
    // colour legend (CommonParams::legend), which moves where the surface leaves room.
    mutable std::optional<LegendLayer> legend_;
};

}  // namespace flowsurf::methods
