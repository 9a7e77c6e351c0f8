// flowsurf — contrast enhancement of the flow texture [doc/contrast.md], the stage between
// a method's flow texture and its overlay, as ParaView's Surface LIC's "enhance contrast":
// the texture's intensity stretched so that its robust range over the surface (the
// enhance-percentile-th and (100 - it)-th percentiles, smoothed over enhance-smoothing
// frames: percentile_range.h) spans [0, 1]. Display only: ISA's and IBFVS's F_a is
// advected on unchanged. The colour's lightness stretch is the overlay's (overlay.h).
// Inputs: F_a or I (R32F), window depth (DEPTH32F, the surface mask) -> the stretched
// texture (R32F). Cost per frame: a histogram pass (one read per pixel, shared-memory
// counts), a 2 KiB read-back that waits for it, a stretch pass (one read, one write per
// pixel); nothing when off. Several processes: the range is the whole image's, in the
// replicate mode from the merged image every process holds, in the tiles mode from the
// histograms of the processes' tiles summed over the group (2 KiB each).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "parallel/process_group.h"
#include "parallel/screen_split.h"
#include "params/params.h"
#include "present/percentile_range.h"

#include <optional>

namespace flowsurf::methods {

class ContrastStretch {
public:
    ContrastStretch(const CommonParams& params, const core::Viewport& viewport);
    bool enabled() const { return enabled_; }
    // (a) The histogram of `flow` over the surface's pixels (`depth` < 1) in `pixels` (every
    // pixel when none), summed over `group` when given, and the smoothed range from it.
    // With a group it is collective: each process of a tiled render counts its own tile
    // (maybe empty), `depth` the whole surface's there. Nothing when not enhanced.
    void measure(const gl::Texture2D& flow, const gl::Texture2D& depth,
                 const std::optional<PixelRect>& pixels = std::nullopt, ProcessGroup* group = nullptr);
    // (b) The texture the overlay shows: `flow` itself when the texture is not enhanced, else
    // `flow` stretched over the measured range at the surface's pixels (valid until the next
    // stretch).
    const gl::Texture2D& stretch(const gl::Texture2D& flow, const gl::Texture2D& depth);
    // (a) over the whole image of this process, then (b).
    const gl::Texture2D& apply(const gl::Texture2D& flow, const gl::Texture2D& depth) {
        measure(flow, depth);
        return stretch(flow, depth);
    }
    // The smoothed range the last frame was stretched over.
    glm::vec2 range() const { return range_.range(); }

private:
    bool enabled_ = false;
    core::Viewport viewport_;
    PercentileRange range_;
    gl::Program histogram_, stretch_;
    gl::Texture2D stretched_;
};

}  // namespace flowsurf::methods
