// flowsurf — measuring a method's frames against the field (doc/algorithms.md, "Quality
// metrics"). The reference is method-independent: one render of the surface into the
// shared G-buffer (methods::SurfaceGBuffer: P-space position and velocity, RGBA32F), whose
// velocity is projected to pixels with the camera's exact Jacobian on the CPU.
// Inputs: a method's F_a (R32F) and surface depth, the surface, the camera -> FrameQuality.
// Cost per measured frame: one G-buffer pass, read-back of 2 RGBA32F + 2 R32F images and a
// few CPU passes (metrics); a kept frame (for the next frame's correlations) reads 2 R32F.
#pragma once

#include "core/camera.h"
#include "methods/frame.h"
#include "quality/frame_metrics.h"
#include "raster/surface_gbuffer.h"

#include <memory>

namespace flowsurf::quality {

// d/dt of the pixel position of posObj moving with velObj (x right, y up, pixels per unit).
glm::vec2 projectedVelocityPx(const glm::mat4& viewProj, const core::Viewport& viewport, const glm::vec3& posObj,
                              const glm::vec3& velObj);

class QualityProbe {
public:
    QualityProbe(const core::Viewport& viewport, const QualityParams& params = {}, bool cullBackFaces = false);
    // Reads back `method`'s frame k (F_a and depth) as the previous frame of frame k + 1.
    void keep(const methods::FlowMethod& method, const core::Camera& camera, uint32_t k);
    // Measures `method`'s frame k of `surface` seen by `camera`; correlations against the
    // kept frame when it is frame k - 1. The frame is then kept for frame k + 1.
    FrameQuality measure(const methods::FlowMethod& method, const methods::SurfaceGpu& surface,
                         const core::Camera& camera, uint32_t k);
    // The sample of the last measured frame (tests compare it with analytic fields).
    const FrameSample& lastSample() const { return now_; }
    const QualityParams& params() const { return params_; }

private:
    void readMethod(const methods::FlowMethod& method, FrameSample& s) const;

    core::Viewport viewport_;
    QualityParams params_;
    methods::SurfaceGBuffer reference_;
    FrameSample now_, prev_;
    core::Camera prevCamera_;
    uint32_t prevFrame_ = 0;
    bool havePrev_ = false;
};

}  // namespace flowsurf::quality
