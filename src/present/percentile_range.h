// flowsurf — robust ranges of per-pixel values for contrast enhancement [doc/contrast.md]:
// a histogram of values in [0, 1] built on the GPU (shaders/present/histogram.glsl: shared
// memory per work group, then one atomic add per non-zero bin), read back small (kBins
// counts, 2 KiB), its low and high percentiles, exponentially smoothed over frames so that
// an animation does not pulse. Deterministic: the counts are integers, the order of the
// atomic adds does not change them.
// Cost per update: the histogram pass (see its shader), one 2 KiB read-back (a sync point:
// the pass must finish) and a scan of the bins on the CPU.
#pragma once

#include "gl/objects.h"
#include "gpu/shader_limits.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace flowsurf::methods {

class ProcessGroup;

// The values at the `percent`-th and (100 - percent)-th percentiles of a histogram of
// kBins-style bins over [0, 1] (bin b holds [b, b + 1) / bins.size()), interpolated
// linearly inside the bin; lo > hi when the histogram is empty.
glm::vec2 histogramPercentiles(std::span<const uint32_t> bins, float percent);

// Exponential smoothing of a range over frames: `previous` moved 1 / `frames` of the way
// towards `now` (frames >= 1; 1: `now`).
glm::vec2 smoothRange(const glm::vec2& previous, const glm::vec2& now, float frames);

class PercentileRange {
public:
    static constexpr int kBins = kHistogramBins;     // over [0, 1]: a bin is 1/512 of the value range
    static constexpr int kTilePx = kHistogramTilePx;  // pixels per side of a work group's block

    PercentileRange() = default;
    // `percent`: clamped at each end, 0..25; `smoothingFrames` >= 1.
    PercentileRange(float percent, float smoothingFrames);
    // Clears the histogram and binds it at HISTOGRAM_BINDING for the pass the caller
    // dispatches next (with dispatchHistogram).
    void bindCleared() const;
    // Runs the bound program (a histogram variant) over width x height pixels.
    static void dispatchHistogram(int width, int height);
    // Reads the histogram back, sums it over `group` when given (collective: a tiled
    // parallel render, each process counting its own tile), and moves the smoothed range
    // towards its percentiles; an empty histogram (no surface in view) keeps the range.
    // Returns the range.
    glm::vec2 update(ProcessGroup* group = nullptr);
    // The smoothed range (lo < hi; [0, 1] before the first update).
    glm::vec2 range() const { return range_; }

private:
    gl::Buffer histogram_;
    float percent_ = 1.0f, smoothing_ = 1.0f;
    glm::vec2 range_{0.0f, 1.0f};
    bool have_ = false;
};

}  // namespace flowsurf::methods
