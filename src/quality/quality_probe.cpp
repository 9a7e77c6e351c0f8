#include "quality/quality_probe.h"

#include "gl/readback.h"

#include <algorithm>
#include <cmath>

namespace flowsurf::quality {

namespace {

// Eye distance along the view axis from window depth z in [0, 1].
float eyeDepth(const core::Camera& c, float z) {
    const float n = c.nearPlane, f = c.farPlane;
    if (c.orthographic()) return n + z * (f - n);
    const float ndc = 2.0f * z - 1.0f;
    return 2.0f * n * f / ((f + n) - ndc * (f - n));
}

}  // namespace

glm::vec2 projectedVelocityPx(const glm::mat4& viewProj, const core::Viewport& viewport, const glm::vec3& posObj,
                              const glm::vec3& velObj) {
    const glm::vec4 clip = viewProj * glm::vec4(posObj, 1.0f), dclip = viewProj * glm::vec4(velObj, 0.0f);
    // d(xy / w) = (dxy w - xy dw) / w^2, then NDC -> pixels.
    const glm::vec2 dNdc = (glm::vec2(dclip) * clip.w - glm::vec2(clip) * dclip.w) / (clip.w * clip.w);
    return dNdc * 0.5f * glm::vec2(float(viewport.width), float(viewport.height));
}

QualityProbe::QualityProbe(const core::Viewport& viewport, const QualityParams& params, bool cullBackFaces)
    : viewport_(viewport), params_(params), reference_(viewport, true, cullBackFaces) {}

void QualityProbe::readMethod(const methods::FlowMethod& method, FrameSample& s) const {
    s.width = viewport_.width;
    s.height = viewport_.height;
    s.flow = gl::readChannel(method.flowTexture(), 0);
    s.depth = gl::readDepth(method.surfaceDepth());
}

void QualityProbe::keep(const methods::FlowMethod& method, const core::Camera& camera, uint32_t k) {
    readMethod(method, prev_);
    prevCamera_ = camera;
    prevFrame_ = k;
    havePrev_ = true;
}

FrameQuality QualityProbe::measure(const methods::FlowMethod& method, const methods::SurfaceGpu& surface,
                                   const core::Camera& camera, uint32_t k) {
    // The reference: the surface's own position and velocity at every pixel.
    reference_.render(surface, camera);
    const std::vector<float> vel = gl::readRgbaFloat(reference_.velocity());
    const std::vector<float> pos = gl::readRgbaFloat(reference_.position());
    readMethod(method, now_);
    const size_t n = now_.flow.size();
    const glm::mat4 viewProj = camera.viewProjection(viewport_.aspect());
    const bool previous = havePrev_ && prevFrame_ + 1 == k;
    now_.layer.assign(n, 0.0f);
    now_.dirPx.assign(n, glm::vec2(0.0f));
    now_.prevPx.assign(previous ? n : 0, glm::vec2(NAN));
    const float depthTolerance = 0.02f * (prevCamera_.farPlane - prevCamera_.nearPlane);
    const glm::mat4 prevViewProj = prevCamera_.viewProjection(viewport_.aspect());  // T(x) of §0, as core::projectToPixels
    for (size_t i = 0; i < n; ++i) {
        now_.layer[i] = vel[4 * i + 3];
        if (now_.layer[i] <= 0.0f) now_.depth[i] = 1.0f;  // the method's pixel the reference does not see
        if (now_.depth[i] >= 1.0f) continue;
        const glm::vec3 p(pos[4 * i], pos[4 * i + 1], pos[4 * i + 2]), v(vel[4 * i], vel[4 * i + 1], vel[4 * i + 2]);
        now_.dirPx[i] = projectedVelocityPx(viewProj, viewport_, p, v);
        if (!previous) continue;
        // Where the point was in the previous image, if it was the visible layer there.
        const glm::vec4 clip = prevViewProj * glm::vec4(p, 1.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        const glm::vec3 q((ndc.x * 0.5f + 0.5f) * float(viewport_.width), (ndc.y * 0.5f + 0.5f) * float(viewport_.height),
                          ndc.z * 0.5f + 0.5f);
        const int x = int(std::floor(q.x)), y = int(std::floor(q.y));
        if (x < 0 || y < 0 || x >= viewport_.width || y >= viewport_.height) continue;
        const float seen = prev_.depth[size_t(y) * viewport_.width + x];
        if (seen < 1.0f && std::abs(eyeDepth(prevCamera_, seen) - eyeDepth(prevCamera_, q.z)) <= depthTolerance)
            now_.prevPx[i] = glm::vec2(q);
    }
    FrameQuality q = measureFrame(now_, previous ? &prev_ : nullptr, params_);
    q.frame = k;
    prev_.width = now_.width;
    prev_.height = now_.height;
    prev_.flow = now_.flow;
    prev_.depth = now_.depth;
    prevCamera_ = camera;
    prevFrame_ = k;
    havePrev_ = true;
    return q;
}

}  // namespace flowsurf::quality
