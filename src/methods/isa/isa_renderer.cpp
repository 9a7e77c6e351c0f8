#include "methods/isa/isa_renderer.h"

#include <cstring>

namespace flowsurf::methods::isa {

namespace {
bool sameCamera(const core::Camera& a, const core::Camera& b) {
    return std::memcmp(&a, &b, sizeof(core::Camera)) == 0;
}
}  // namespace

IsaRenderer::IsaRenderer(const MethodParams& params, const core::Viewport& viewport)
    : params_(params),
      viewport_(viewport),
      velocityImage_(viewport),
      advectionMesh_(viewport, params.isa.gridRes),
      textureAdvection_(params.isa.gridRes, params.isa.warp),
      overlay_(params.common),
      composite_(GL_RGBA8, viewport.width, viewport.height, GL_NEAREST),
      compositeFbo_(gl::Framebuffer::create()) {
    const float gray[4] = {0.5f, 0.0f, 0.0f, 1.0f};  // start at the noise mean
    for (int i = 0; i < 2; ++i) {
        flow_[i] = gl::Texture2D(GL_R32F, viewport.width, viewport.height, GL_LINEAR);
        flowFbo_[i] = gl::Framebuffer::create();
        flowFbo_[i].attach(GL_COLOR_ATTACHMENT0, flow_[i]);
        flowFbo_[i].finish(1);
        glClearNamedFramebufferfv(flowFbo_[i].id(), GL_COLOR, 0, gray);
    }
    compositeFbo_.attach(GL_COLOR_ATTACHMENT0, composite_);
    compositeFbo_.finish(1);
}

bool IsaRenderer::isDynamic(const FrameInput& in) const {
    return !haveCache_ || in.surface->generation() != cachedGeneration_ || !sameCamera(in.camera, cachedCamera_);
}

void IsaRenderer::renderFrame(const FrameInput& in) {
    const CommonParams& c = params_.common;
    const int prev = current_, next = 1 - current_;
    timer_.beginFrame();

    // Dynamic case [L Table II]: view, geometry or data changed. Static: reuse (1)-(2).
    lastDynamic_ = isDynamic(in);
    if (lastDynamic_) {
        // (1) velocity image: mesh with per-vertex velocity, nearest layer [L §IV-C.1]
        timer_.begin("velocity image");
        velocityImage_.render(*in.surface, in.camera);

        // (2) advection mesh + edge detection [L §IV-D.1, eq. 12, eq. 14]
        timer_.begin("advection mesh");
        advectionMesh_.compute(velocityImage_.velocity(), velocityImage_.depth(), in.camera,
                               dtForStep(in, viewport_, c.stepPx), params_.isa.edgeEpsilon);
        haveCache_ = true;
        cachedGeneration_ = in.surface->generation();
        cachedCamera_ = in.camera;
    }

    // (3) texture advection with edge blending [L §IV-D.1, §IV-E.1]
    timer_.begin("texture advection");
    textureAdvection_.apply(advectionMesh_.vertices(), flow_[prev], flowFbo_[next], params_.isa.edgeBlending,
                            0.5f);

    // (4) noise injection and blending on the surface only [L eq. 9]
    timer_.begin("noise blend");
    noiseInjection_.apply(flowFbo_[next], velocityImage_.depth(), in.frame, c.alpha, c.noise);
    current_ = next;

    // (5) overlay with texture clipping and velocity mask [L eq. 10, Fig. 10]
    timer_.begin("overlay");
    overlay_.apply(flow_[current_], velocityImage_.depth(), velocityImage_.shade(), compositeFbo_,
                   in.surface->colorSpeedMax());
    timer_.endFrame();
}

}  // namespace flowsurf::methods::isa
