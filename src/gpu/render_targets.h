// flowsurf — the render targets every method keeps: a colour texture with its
// framebuffer (the composite, the hybrid's LIC image), and the ping-pong pair of F_a
// textures that ISA and IBFVS advect from one into the other.
#pragma once

#include "core/camera.h"
#include "gl/objects.h"

#include <initializer_list>
#include <utility>

namespace flowsurf::methods {

// One texture as the only colour attachment of a framebuffer.
class ColorTarget {
public:
    ColorTarget(GLenum format, const core::Viewport& viewport, GLenum filter = GL_NEAREST);
    const gl::Texture2D& texture() const { return texture_; }
    const gl::Framebuffer& fbo() const { return fbo_; }

private:
    gl::Texture2D texture_;
    gl::Framebuffer fbo_;
};

// F_a (R32F, linear filtering) twice, both started at the noise mean. `shared`
// attachments (IBFVS: the shade image and the depth buffer its advection draw writes)
// are attached to both framebuffers after F_a; colour ones count as draw buffers.
class FlowPingPong {
public:
    using Attachment = std::pair<GLenum, const gl::Texture2D*>;
    FlowPingPong(const core::Viewport& viewport, std::initializer_list<Attachment> shared = {});
    const gl::Texture2D& texture(int i) const { return flow_[i]; }
    const gl::Framebuffer& fbo(int i) const { return fbo_[i]; }

private:
    gl::Texture2D flow_[2];
    gl::Framebuffer fbo_[2];
};

}  // namespace flowsurf::methods
