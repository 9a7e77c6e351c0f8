// flowsurf — contrast enhancement of the flow texture [issue 28 item 2], the stage between
// a method's flow texture and its overlay, as ParaView's Surface LIC's "enhance contrast":
// the texture's intensity stretched so that its robust range over the surface (the
// enhance-percentile-th and (100 - it)-th percentiles, smoothed over enhance-smoothing
// frames: percentile_range.h) spans [0, 1]. Display only: ISA's and IBFVS's F_a is
// advected on unchanged. The colour's lightness stretch is the overlay's (overlay.h).
// Inputs: F_a or I (R32F), window depth (DEPTH32F, the surface mask) -> the stretched
// texture (R32F). Cost per frame: a histogram pass (one read per pixel, shared-memory
// counts), a 2 KiB read-back that waits for it, a stretch pass (one read, one write per
// pixel); nothing when off. Several processes: the range is the whole image's in the
// replicate mode (every process holds the merged image); the tiles mode is refused.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/params.h"
#include "methods/common/percentile_range.h"

namespace flowsurf::methods {

struct FrameInput;

class ContrastStretch {
public:
    ContrastStretch(const CommonParams& params, const core::Viewport& viewport);
    bool enabled() const { return enabled_; }
    // The texture the overlay shows: `flow` itself when the texture is not enhanced, else
    // its stretch (valid until the next apply).
    const gl::Texture2D& apply(const gl::Texture2D& flow, const gl::Texture2D& depth);
    // The smoothed range the last frame was stretched over.
    glm::vec2 range() const { return range_.range(); }

private:
    bool enabled_ = false;
    core::Viewport viewport_;
    PercentileRange range_;
    gl::Program histogram_, stretch_;
    gl::Texture2D stretched_;
};

// Throws ConfigError when `params` enhance contrast in a tiled parallel render: the
// percentiles must be the whole image's, which no process of the tiles mode holds.
void checkContrastParallel(const FrameInput& in, const CommonParams& params);

}  // namespace flowsurf::methods
