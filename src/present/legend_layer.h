// flowsurf — the colour legend as a layer of the overlay [docs/cfd.md, colour ranges]: the
// legend image (legend.h) at the largest of its sizes that finds a place covering no surface
// pixel, kept where it is while that place stays free (no jumping in a movie), and left out
// (the user told once) where no place is free. Input: the surface's window depth.
#pragma once

#include "gl/objects.h"
#include "params/params.h"
#include "present/legend.h"
#include "raster/surface_gpu.h"

#include <string>
#include <vector>

namespace flowsurf::methods {

class LegendLayer {
public:
    explicit LegendLayer(const CommonParams& params) : params_(params) {}
    // Re-rasterises the legend when its range or title changed (auto ranges move), and
    // places it where it covers no surface pixel of `depth`, smaller if it must be.
    void place(const SurfaceGpu& surface, const gl::Texture2D& depth);
    // The placed legend into `prog` (the overlay's uLegendOrigin and legend image unit).
    void bind(const gl::Program& prog) const;

private:
    // The legend at each size tried (full, then smaller), rasterised when first needed.
    struct Size {
        int imageHeight = 0;  // the image height makeLegendImage sizes it for
        LegendLayout layout = LegendLayout::Vertical;
        glm::ivec2 size{0};
        gl::Texture2D texture;
    };
    Size& sized(size_t i, int imageHeight);

    CommonParams params_;
    std::vector<Size> sizes_;
    size_t shown_ = 0;        // index into sizes_
    glm::ivec2 origin_{0};
    bool placed_ = false;     // origin_ is a free place found earlier
    bool warned_ = false;     // told that no place was free
    LegendScale scale_;
    std::string title_;
};

}  // namespace flowsurf::methods
