// IBFVS stages 1-3 — object-space mesh projection [L eq. 13] (in the vertex shader,
// shaders/ibfvs/mesh_projection.glsl), polygonal texture advection [L §IV-D.2] and noise
// injection [L eq. 9] (shaders/ibfvs/polygon_advection.*): one draw of the surface mesh
// into the next F_a (R32F), sampling the previous F_a; also writes shade (RGBA16F) and
// depth. Cost grows with the triangles N, in the static and the dynamic case alike. F_a
// is resampled bilinearly (as in [L]) or bicubically (shaders/common/resample.glsl).
#pragma once

#include "core/camera.h"
#include "gl/objects.h"
#include "methods/common/noise_injection.h"
#include "methods/common/params.h"
#include "methods/common/surface_gpu.h"

namespace flowsurf::methods::ibfvs {

class PolygonAdvection {
public:
    // `common`: the resampling, and the noise injection mode, scale and step.
    PolygonAdvection(const core::Viewport& viewport, const CommonParams& common);
    // `prevCamera` projects the pathline points into the previous F_a.
    void apply(const SurfaceGpu& surface, const core::Camera& camera, const core::Camera& prevCamera,
               const core::Viewport& viewport, float dt, const gl::Texture2D& prevFlow,
               const gl::Framebuffer& target, float flowBackground, bool cullBackFaces,
               const NoiseStep& noise) const;

private:
    NoiseInjection noise_;
    gl::Program program_;
};

}  // namespace flowsurf::methods::ibfvs
