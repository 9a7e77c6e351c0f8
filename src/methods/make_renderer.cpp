#include "methods/make_renderer.h"

#include "core/errors.h"
#include "methods/hybrid/hybrid_renderer.h"
#include "methods/ibfvs/ibfvs_renderer.h"
#include "methods/isa/isa_renderer.h"

#include <cstdio>

namespace flowsurf::methods {

namespace {
std::unique_ptr<FlowMethod> construct(Method method, const MethodParams& params, const core::Viewport& viewport,
                                      ProcessGroup* group) {
    // Oriented LIC needs a kernel that is applied at once along the whole streamline; ISA's and
    // IBFVS's noise injection (eq. 9) blends over past frames instead, which weights a streak
    // most where the noise was injected last, at its upstream end.
    if (params.hybrid.oriented && method != Method::Hybrid)
        throw ConfigError("--oriented on: only the hybrid method draws oriented streaks (ISA's and IBFVS's noise "
                          "injection gives no sound one-sided kernel); use --method hybrid, or --oriented off");
    if (params.hybrid.oriented && params.hybrid.kernel == LicKernel::Box)
        throw ConfigError("--oriented on with --kernel box: the drops take the kernel's falloff from their head and a "
                          "box has none; use --kernel gaussian (the default), exponential or hann");
    switch (method) {
        case Method::Isa: return std::make_unique<isa::IsaRenderer>(params, viewport, group);
        case Method::Ibfvs: return std::make_unique<ibfvs::IbfvsRenderer>(params, viewport, group);
        case Method::Hybrid:
            if (params.hybrid.noiseSize != 64 && params.hybrid.noiseSize != 128)
                throw ConfigError("--noise-size must be 64 or 128");
            return std::make_unique<hybrid::HybridRenderer>(params, viewport, group);
    }
    throw ConfigError("unknown method");
}
}  // namespace

Method methodFromName(const std::string& name) {
    Method m{};
    if (!valueOf(kMethodNames, name, &m))
        throw ConfigError("unknown method '" + name + "' (available: " + nameList(kMethodNames) + ")");
    return m;
}

std::unique_ptr<FlowMethod> makeMethod(const std::string& name, const MethodParams& params,
                                       const core::Viewport& viewport, ProcessGroup* group) {
    return makeRenderer(methodFromName(name), params, viewport, group);
}

std::unique_ptr<FlowMethod> makeRenderer(Method method, const MethodParams& params, const core::Viewport& viewport,
                                         ProcessGroup* group) {
    const std::string name(nameOf(kMethodNames, method));
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (viewport.width > maxSize || viewport.height > maxSize)
        throw ConfigError("image size " + std::to_string(viewport.width) + "x" + std::to_string(viewport.height) +
                          " exceeds this OpenGL's largest texture (" + std::to_string(maxSize) + ")");
    while (glGetError() != GL_NO_ERROR) {
    }
    std::unique_ptr<FlowMethod> renderer;
    try {
        renderer = construct(method, params, viewport, group);
    } catch (const GlError& e) {  // e.g. render targets without memory: say for what
        throw GlError(std::string(e.what()) + " setting up method " + name + " at " + std::to_string(viewport.width) +
                      "x" + std::to_string(viewport.height));
    }
    // Render targets are allocated above: an absurd size shows up here, not as a crash.
    if (GLenum err = glGetError(); err == GL_OUT_OF_MEMORY)
        throw GlError("not enough graphics memory for " + std::to_string(viewport.width) + "x" +
                      std::to_string(viewport.height) + " with method " + name);
    else if (err != GL_NO_ERROR)
    {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04X", unsigned(err));
        throw GlError(std::string("OpenGL error ") + hex + " while setting up method " + name);
    }
    return renderer;
}

}  // namespace flowsurf::methods
