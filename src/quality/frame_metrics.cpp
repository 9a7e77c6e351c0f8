// Index: metric table · orientation · correlations · contrast · frequency · frame, summary.
#include "quality/frame_metrics.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::quality {

namespace {

// Too few pixels for a number worth reporting.
constexpr size_t kMinPixels = 64;

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return kNoValue;
    const size_t i = std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(i), v.end());
    return v[i];
}

struct Moments {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    size_t n = 0;
    void add(double a, double b) {
        sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b;
        ++n;
    }
    double pearson() const {
        if (n < kMinPixels) return kNoValue;
        const double m = double(n), cov = sab / m - sa / m * sb / m;
        const double va = saa / m - sa / m * sa / m, vb = sbb / m - sb / m * sb / m;
        return va * vb > 1e-20 ? cov / std::sqrt(va * vb) : kNoValue;
    }
};

// Bilinear F_a at pixel coordinates (centres at +0.5) if all four taps are on the surface.
bool sampleOnSurface(const FrameSample& s, glm::vec2 px, double* value) {
    const float fx = px.x - 0.5f, fy = px.y - 0.5f;
    if (!(fx >= 0.0f && fy >= 0.0f && fx < float(s.width - 1) && fy < float(s.height - 1))) return false;
    const int x = int(fx), y = int(fy);
    const float tx = fx - float(x), ty = fy - float(y);
    const size_t i = size_t(y) * s.width + x, up = size_t(s.width);
    if (s.depth[i] >= 1.0f || s.depth[i + 1] >= 1.0f || s.depth[i + up] >= 1.0f || s.depth[i + up + 1] >= 1.0f)
        return false;
    *value = (1 - ty) * ((1 - tx) * s.flow[i] + tx * s.flow[i + 1]) + ty * ((1 - tx) * s.flow[i + up] + tx * s.flow[i + up + 1]);
    return true;
}

// Speed below which the projected direction is not trusted: a fraction of the 95th percentile.
float speedFloor(const FrameSample& s, const QualityParams& p) {
    std::vector<double> speeds;
    for (size_t i = 0; i < s.depth.size(); ++i)
        if (s.depth[i] < 1.0f) speeds.push_back(glm::length(s.dirPx[i]));
    const double p95 = percentile(speeds, 0.95);
    return std::isnan(p95) ? 0.0f : float(p.minSpeed * p95);
}

}  // namespace

// --- metric table --------------------------------------------------------------------------

const std::array<MetricInfo, 8>& metricTable() {
    static const std::array<MetricInfo, 8> table{{
        {"orientation_error_deg", &FrameQuality::orientationErrorDeg, Worse::Higher,
         "median angle between the texture's streaks and the projected field (degrees)"},
        {"orientation_error_p90_deg", &FrameQuality::orientationErrorP90Deg, Worse::Higher,
         "90th percentile of that angle (degrees)"},
        {"counted_fraction", &FrameQuality::countedFraction, Worse::Lower,
         "surface pixels with coherent streaks where the field is not too slow"},
        {"frame_correlation", &FrameQuality::frameCorrelation, Worse::Lower,
         "correlation of consecutive frames' F_a, same pixels (1: frozen, 0: flicker)"},
        {"frame_correlation_reprojected", &FrameQuality::frameCorrelationReprojected, Worse::Lower,
         "the same, following each surface point with the camera"},
        {"contrast", &FrameQuality::contrast, Worse::Lower, "standard deviation of F_a over the surface"},
        {"edge_contrast_ratio", &FrameQuality::edgeContrastRatio, Worse::Lower,
         "contrast near silhouettes and depth edges / contrast in the interior"},
        {"frequency_px", &FrameQuality::frequencyPx, Worse::Farther,
         "feature size across the flow (pixels)"},
    }};
    return table;
}

// --- orientation -----------------------------------------------------------------------------

std::vector<uint8_t> countedPixels(const FrameSample& s, const std::vector<Streak>& streaks, const QualityParams& p) {
    const float floor = speedFloor(s, p);
    std::vector<uint8_t> counted(s.depth.size(), 0);
    for (size_t i = 0; i < s.depth.size(); ++i) {
        const float speed = glm::length(s.dirPx[i]);
        counted[i] = s.depth[i] < 1.0f && streaks[i].coherence >= p.minCoherence && speed > floor && speed > 0.0f;
    }
    return counted;
}

OrientationStats orientationError(const FrameSample& s, const std::vector<Streak>& streaks, const QualityParams& p) {
    const std::vector<uint8_t> counted = countedPixels(s, streaks, p);
    std::vector<double> errors;
    size_t surface = 0;
    for (size_t i = 0; i < s.depth.size(); ++i) {
        surface += s.depth[i] < 1.0f;
        if (counted[i]) errors.push_back(orientationErrorDeg(streaks[i].angle, std::atan2(s.dirPx[i].y, s.dirPx[i].x)));
    }
    OrientationStats o;
    if (surface == 0) return o;
    o.countedFraction = double(errors.size()) / double(surface);
    if (errors.size() < kMinPixels) return o;
    o.medianDeg = percentile(errors, 0.5);
    o.p90Deg = percentile(errors, 0.9);
    return o;
}

// --- correlations ----------------------------------------------------------------------------

double frameCorrelation(const FrameSample& now, const FrameSample& prev) {
    Moments m;
    for (size_t i = 0; i < now.depth.size(); ++i)
        if (now.depth[i] < 1.0f && prev.depth[i] < 1.0f) m.add(now.flow[i], prev.flow[i]);
    return m.pearson();
}

double reprojectedCorrelation(const FrameSample& now, const FrameSample& prev) {
    if (now.prevPx.empty()) return kNoValue;
    Moments m;
    double v = 0;
    for (size_t i = 0; i < now.depth.size(); ++i)
        if (now.depth[i] < 1.0f && sampleOnSurface(prev, now.prevPx[i], &v)) m.add(now.flow[i], v);
    return m.pearson();
}

// --- contrast ----------------------------------------------------------------------------------

ContrastStats contrast(const FrameSample& s, const QualityParams& p) {
    const int w = s.width, h = s.height;
    // Edge pixels: on the surface with a 4-neighbour off it or on another layer (a depth
    // step over 1% of the depth range); the band is their Chebyshev neighbourhood.
    std::vector<uint8_t> band(s.depth.size(), 0);
    auto on = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h && s.depth[size_t(y) * w + x] < 1.0f; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!on(x, y)) continue;
            const float l = s.layer[size_t(y) * w + x];
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
                if (!on(x + dx, y + dy) || std::abs(s.layer[size_t(y + dy) * w + x + dx] - l) > 0.01f)
                    band[size_t(y) * w + x] = 1;
        }
    // Chebyshev dilation by edgeBandPx: along rows, then along columns.
    auto dilate = [&](int stepX, int stepY) {
        std::vector<uint8_t> next(band.size(), 0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int i = -p.edgeBandPx; i <= p.edgeBandPx; ++i) {
                    const int px = x + i * stepX, py = y + i * stepY;
                    if (px >= 0 && py >= 0 && px < w && py < h && band[size_t(py) * w + px]) {
                        next[size_t(y) * w + x] = 1;
                        break;
                    }
                }
        band.swap(next);
    };
    dilate(1, 0);
    dilate(0, 1);
    struct Acc {
        double s = 0, s2 = 0;
        size_t n = 0;
        void add(double v) { s += v, s2 += v * v, ++n; }
        double std() const { return n < kMinPixels ? kNoValue : std::sqrt(std::max(0.0, s2 / double(n) - (s / double(n)) * (s / double(n)))); }
    } all, edge, interior;
    for (size_t i = 0; i < s.depth.size(); ++i) {
        if (s.depth[i] >= 1.0f) continue;
        all.add(s.flow[i]);
        (band[i] ? edge : interior).add(s.flow[i]);
    }
    ContrastStats c;
    c.std = all.std();
    const double e = edge.std(), in = interior.std();
    if (!std::isnan(e) && !std::isnan(in) && in > 1e-9) c.edgeRatio = e / in;
    return c;
}

// --- frequency -----------------------------------------------------------------------------------

double frequencyPx(const FrameSample& s, const QualityParams& p) {
    double mean = 0, m2 = 0;
    size_t n = 0;
    for (size_t i = 0; i < s.depth.size(); ++i)
        if (s.depth[i] < 1.0f) mean += s.flow[i], m2 += double(s.flow[i]) * s.flow[i], ++n;
    if (n < kMinPixels) return kNoValue;
    mean /= double(n);
    const double var = m2 / double(n) - mean * mean;
    if (var <= 1e-12) return kNoValue;
    // Samples on a 2-pixel grid where the field's direction is trusted; across = its normal.
    const float floor = speedFloor(s, p);
    struct Sample {
        glm::vec2 px, across;
        double f;
    };
    std::vector<Sample> samples;
    for (int y = 0; y < s.height; y += 2)
        for (int x = 0; x < s.width; x += 2) {
            const size_t i = size_t(y) * s.width + x;
            const glm::vec2 d = s.dirPx[i];
            if (s.depth[i] >= 1.0f || glm::length(d) <= floor || glm::length(d) == 0.0f) continue;
            const glm::vec2 u = glm::normalize(d);
            samples.push_back({glm::vec2(x + 0.5f, y + 0.5f), glm::vec2(-u.y, u.x), s.flow[i] - mean});
        }
    if (samples.size() < kMinPixels) return kNoValue;
    double prev = 1.0, v = 0;
    for (int lag = 1; lag <= p.maxLagPx; ++lag) {
        double c = 0;
        size_t m = 0;
        for (const Sample& a : samples)
            for (float sign : {-1.0f, 1.0f})
                if (sampleOnSurface(s, a.px + sign * float(lag) * a.across, &v)) c += a.f * (v - mean), ++m;
        if (m < kMinPixels) return kNoValue;
        const double rho = c / double(m) / var;
        if (rho < 0.5) return 2.0 * (double(lag - 1) + (prev - 0.5) / (prev - rho));  // linear crossing
        prev = rho;
    }
    return kNoValue;
}

// --- frame, summary --------------------------------------------------------------------------------

FrameQuality measureFrame(const FrameSample& now, const FrameSample* prev, const QualityParams& p) {
    FrameQuality q;
    const OrientationStats o = orientationError(now, streakField(now.image(), p.sigmaPx), p);
    q.orientationErrorDeg = o.medianDeg;
    q.orientationErrorP90Deg = o.p90Deg;
    q.countedFraction = o.countedFraction;
    if (prev) {
        q.frameCorrelation = frameCorrelation(now, *prev);
        q.frameCorrelationReprojected = reprojectedCorrelation(now, *prev);
    }
    const ContrastStats c = contrast(now, p);
    q.contrast = c.std;
    q.edgeContrastRatio = c.edgeRatio;
    q.frequencyPx = frequencyPx(now, p);
    return q;
}

QualitySummary summarize(const std::vector<FrameQuality>& frames) {
    QualitySummary s;
    s.frames = int(frames.size());
    if (!frames.empty()) s.median.frame = frames.front().frame, s.worst.frame = frames.back().frame;
    for (const MetricInfo& m : metricTable()) {
        std::vector<double> v;
        for (const FrameQuality& f : frames)
            if (!std::isnan(f.*m.member)) v.push_back(f.*m.member);
        if (v.empty()) continue;
        const double median = percentile(v, 0.5);
        s.median.*m.member = median;
        double worst = v.front();
        for (double x : v) {
            if (m.worse == Worse::Higher) worst = std::max(worst, x);
            else if (m.worse == Worse::Lower) worst = std::min(worst, x);
            else if (std::abs(std::log(x / median)) > std::abs(std::log(worst / median))) worst = x;
        }
        s.worst.*m.member = worst;
    }
    return s;
}

}  // namespace flowsurf::quality
