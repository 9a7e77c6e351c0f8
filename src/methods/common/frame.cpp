#include "methods/common/frame.h"

#include "core/errors.h"
#include "methods/hybrid/hybrid_renderer.h"
#include "methods/ibfvs/ibfvs_renderer.h"
#include "methods/isa/isa_renderer.h"

#include <algorithm>

namespace flowsurf::methods {

namespace {
std::unique_ptr<FlowMethod> construct(const std::string& name, const MethodParams& params,
                                      const core::Viewport& viewport) {
    if (name == "isa") return std::make_unique<isa::IsaRenderer>(params, viewport);
    if (name == "ibfvs") return std::make_unique<ibfvs::IbfvsRenderer>(params, viewport);
    if (name == "hybrid") {
        if (params.hybrid.noiseSize != 64 && params.hybrid.noiseSize != 128)
            throw ConfigError("--noise-size must be 64 or 128");
        return std::make_unique<hybrid::HybridRenderer>(params, viewport);
    }
    throw ConfigError("unknown method '" + name + "' (available: isa, ibfvs, hybrid)");
}
}  // namespace

std::unique_ptr<FlowMethod> makeMethod(const std::string& name, const MethodParams& params,
                                       const core::Viewport& viewport) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (viewport.width > maxSize || viewport.height > maxSize)
        throw ConfigError("image size " + std::to_string(viewport.width) + "x" + std::to_string(viewport.height) +
                          " exceeds this OpenGL's largest texture (" + std::to_string(maxSize) + ")");
    while (glGetError() != GL_NO_ERROR) {
    }
    std::unique_ptr<FlowMethod> method = construct(name, params, viewport);
    // Render targets are allocated above: an absurd size shows up here, not as a crash.
    if (GLenum err = glGetError(); err == GL_OUT_OF_MEMORY)
        throw GlError("not enough graphics memory for " + std::to_string(viewport.width) + "x" +
                      std::to_string(viewport.height) + " with method " + name);
    else if (err != GL_NO_ERROR)
        throw GlError("OpenGL error 0x" + std::to_string(err) + " while setting up method " + name);
    return method;
}

float dtForStep(const FrameInput& in, const core::Viewport& viewport, float stepPx) {
    float speed = in.surface->maxSpeed();
    if (speed <= 0.0f) return 0.0f;
    float pxPerUnit = core::maxPixelsPerUnit(in.camera, viewport, in.surface->bounds());
    return stepPx / (speed * std::max(pxPerUnit, 1e-30f));
}

}  // namespace flowsurf::methods
