// flowsurf — how faithful one frame of a flow texture is to the field it shows: the
// metrics of doc/algorithms.md ("Quality metrics"), computed on the CPU from one read-back
// frame and the projected field of the same pixels (quality_probe.h makes both).
// Inputs: F_a (R32F), window depth, the reference's layer depth and projected field,
// rows bottom to top -> FrameQuality. Cost: a few passes over the pixels, no GL.
#pragma once

#include "quality/structure_tensor.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace flowsurf::quality {

struct QualityParams {
    float sigmaPx = 3.0f;          // structure tensor scale: Gaussian sigma in pixels (2..8)
    float minCoherence = 0.3f;     // pixels with less coherent structure are not counted (0..1)
    float minSpeed = 0.05f;        // ... nor where the projected speed is below this fraction of its 95th percentile
    int edgeBandPx = 4;            // width of the band along silhouettes and depth edges (pixels)
    int maxLagPx = 64;             // longest lag of the across-flow autocorrelation (pixels)
};

inline constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

// One frame's numbers; NaN where a metric has too few pixels or no previous frame.
struct FrameQuality {
    uint32_t frame = 0;                          // noise clock k of the frame
    double orientationErrorDeg = kNoValue;       // median over the counted pixels
    double orientationErrorP90Deg = kNoValue;    // 90th percentile over the counted pixels
    double countedFraction = kNoValue;           // counted pixels / surface pixels
    double frameCorrelation = kNoValue;          // F_a(k) vs F_a(k-1), same pixels
    double frameCorrelationReprojected = kNoValue;  // ... at the surface point's pixel in frame k-1
    double contrast = kNoValue;                  // std of F_a over the surface
    double edgeContrastRatio = kNoValue;         // std near silhouettes / std in the interior
    double frequencyPx = kNoValue;               // feature size across the flow, pixels
};

// The metrics by name, in report order: the command line's table, the JSON files, the
// library, Python and the viewer all read this table.
enum class Worse { Higher, Lower, Farther };  // which way a frame is worse (summaries)
struct MetricInfo {
    const char* name;
    double FrameQuality::*member;
    Worse worse;
    const char* help;
};
const std::array<MetricInfo, 8>& metricTable();

// One frame as the metrics see it; every vector has width * height entries.
struct FrameSample {
    int width = 0, height = 0;
    std::vector<float> flow;        // F_a
    std::vector<float> depth;       // window depth, 1: background (the method's, where the reference sees the surface)
    std::vector<float> layer;       // the reference's layer depth (methods::layerDepthRow, 1..2; 0: background)
    std::vector<glm::vec2> dirPx;   // projected field, pixels per unit time (0: background)
    // Where this pixel's surface point was in the previous frame's image (pixels, centres
    // at +0.5), NaN where unknown or hidden there; empty: no previous frame.
    std::vector<glm::vec2> prevPx;
    SurfaceImage image() const { return {width, height, flow.data(), depth.data()}; }
};

struct OrientationStats {
    double medianDeg = kNoValue, p90Deg = kNoValue, countedFraction = kNoValue;
};
// The pixels the orientation error counts: on the surface, coherence >= minCoherence and
// projected speed above minSpeed times its 95th percentile over the surface.
std::vector<uint8_t> countedPixels(const FrameSample& s, const std::vector<Streak>& streaks, const QualityParams& p);
OrientationStats orientationError(const FrameSample& s, const std::vector<Streak>& streaks, const QualityParams& p);
// Pearson correlation of F_a over pixels on the surface in both frames.
double frameCorrelation(const FrameSample& now, const FrameSample& prev);
// The same with the previous frame sampled (bilinearly) where now's surface point was.
double reprojectedCorrelation(const FrameSample& now, const FrameSample& prev);
struct ContrastStats {
    double std = kNoValue, edgeRatio = kNoValue;
};
ContrastStats contrast(const FrameSample& s, const QualityParams& p);
// Twice the lag at which the autocorrelation of F_a across the projected field falls to 1/2.
double frequencyPx(const FrameSample& s, const QualityParams& p);

// Every metric of `now` (correlations only with `prev`, the frame just before).
FrameQuality measureFrame(const FrameSample& now, const FrameSample* prev, const QualityParams& p);

// An animation's numbers: the median over frames and the worst frame of each metric
// (highest error, lowest fraction, correlation and contrast, feature size farthest from
// the median); NaN frames are skipped.
struct QualitySummary {
    int frames = 0;
    FrameQuality median, worst;
};
QualitySummary summarize(const std::vector<FrameQuality>& frames);

}  // namespace flowsurf::quality
