#include "gpu/render_targets.h"

#include "core/noise.h"
#include "gpu/gpu_bindings.h"

namespace flowsurf::methods {

ColorTarget::ColorTarget(GLenum format, const core::Viewport& viewport, GLenum filter)
    : texture_(format, viewport.width, viewport.height, filter), fbo_(gl::Framebuffer::create()) {
    fbo_.attach(GL_COLOR_ATTACHMENT0, texture_);
    fbo_.finish(1);
}

FlowPingPong::FlowPingPong(const core::Viewport& viewport, std::initializer_list<Attachment> shared) {
    const float mean[4] = {core::kNoiseMean, 0.0f, 0.0f, 1.0f};
    for (int i = 0; i < 2; ++i) {
        flow_[i] = gl::Texture2D(GL_R32F, viewport.width, viewport.height, GL_LINEAR);
        fbo_[i] = gl::Framebuffer::create();
        fbo_[i].attach(GL_COLOR_ATTACHMENT0 + outputs::kFlow, flow_[i]);
        int colors = 1;
        for (const auto& [attachment, texture] : shared) {
            fbo_[i].attach(attachment, *texture);
            colors += attachment >= GL_COLOR_ATTACHMENT0 && attachment <= GL_COLOR_ATTACHMENT15;
        }
        fbo_[i].finish(colors);
        glClearNamedFramebufferfv(fbo_[i].id(), GL_COLOR, outputs::kFlow, mean);
    }
}

}  // namespace flowsurf::methods
