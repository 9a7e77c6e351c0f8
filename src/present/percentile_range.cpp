#include "present/percentile_range.h"

#include "gpu/shader_interface.h"
#include "parallel/process_group.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flowsurf::methods {

namespace {
// The narrowest stretched range: a gain of at most 20 about its middle, so that a nearly
// flat image (a constant texture, a surface seen edge-on) does not amplify rounding.
constexpr float kMinSpan = 1.0f / 20.0f;
}  // namespace

glm::vec2 histogramPercentiles(std::span<const uint32_t> bins, float percent) {
    uint64_t total = 0;
    for (uint32_t b : bins) total += b;
    if (total == 0 || bins.empty()) return {1.0f, 0.0f};
    const double binWidth = 1.0 / double(bins.size());
    // The value below which `rank` of the `total` counts lie, linear inside its bin.
    auto valueAt = [&](double rank) {
        double below = 0.0;
        for (size_t b = 0; b < bins.size(); ++b) {
            const double n = bins[b];
            if (n > 0.0 && below + n >= rank) return float((double(b) + std::clamp((rank - below) / n, 0.0, 1.0)) * binWidth);
            below += n;
        }
        return 1.0f;
    };
    const double p = std::clamp(double(percent), 0.0, 50.0) / 100.0;
    return {valueAt(p * double(total)), valueAt((1.0 - p) * double(total))};
}

glm::vec2 smoothRange(const glm::vec2& previous, const glm::vec2& now, float frames) {
    const float w = 1.0f / std::max(frames, 1.0f);
    return previous + (now - previous) * w;
}

PercentileRange::PercentileRange(float percent, float smoothingFrames)
    : histogram_(GLsizeiptr(kBins * sizeof(uint32_t)), nullptr), percent_(percent), smoothing_(smoothingFrames) {}

void PercentileRange::bindCleared() const {
    glClearNamedBufferData(histogram_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, bindings::kHistogram, histogram_.id());
}

void PercentileRange::dispatchHistogram(int width, int height) {
    glDispatchCompute(GLuint((width + kTilePx - 1) / kTilePx), GLuint((height + kTilePx - 1) / kTilePx), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

glm::vec2 PercentileRange::update(ProcessGroup* group) {
    std::vector<uint32_t> bins(static_cast<size_t>(kBins));
    glGetNamedBufferSubData(histogram_.id(), 0, GLsizeiptr(bins.size() * sizeof(uint32_t)), bins.data());
    if (group) {
        // Counts as floats: exact below 2^24 per bin (a 4096^2 image has 2^24 pixels).
        std::vector<float> sum(bins.begin(), bins.end());
        group->sumInPlace(sum);
        for (size_t b = 0; b < bins.size(); ++b) bins[b] = uint32_t(sum[b]);
    }
    glm::vec2 now = histogramPercentiles(bins, percent_);
    if (now.x > now.y) return range_;  // nothing counted: keep the range
    if (now.y - now.x < kMinSpan) {
        const float mid = 0.5f * (now.x + now.y);
        now = {mid - 0.5f * kMinSpan, mid + 0.5f * kMinSpan};
    }
    range_ = have_ ? smoothRange(range_, now, smoothing_) : now;
    have_ = true;
    return range_;
}

}  // namespace flowsurf::methods
