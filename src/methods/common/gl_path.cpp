#include "methods/common/gl_path.h"

#include <epoxy/gl.h>

#include <array>
#include <utility>

namespace flowsurf::methods {

namespace {

// Renderer substring -> the faster path there, first match wins (doc/bench: fragment vs
// compute per stage). Anything unlisted takes the fragment path, the one every GL 4.5
// driver has run longest.
constexpr std::array<std::pair<std::string_view, GlPath>, 2> kAutoRule{{
    {"NVIDIA", GlPath::Compute},
    {"llvmpipe", GlPath::Fragment},
}};

}  // namespace

GlPath glPathFor(GlPath requested, std::string_view renderer) {
    if (requested != GlPath::Auto) return requested;
    for (const auto& [name, path] : kAutoRule)
        if (renderer.find(name) != std::string_view::npos) return path;
    return GlPath::Fragment;
}

std::string_view currentRenderer() {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return r ? std::string_view(r) : std::string_view();
}

GlPath resolveGlPath(GlPath requested) {
    if (requested != GlPath::Auto) return requested;
    return glPathFor(requested, currentRenderer());
}

bool useComputeRaster(SurfaceRaster requested, std::string_view renderer, size_t triangles, size_t pixels) {
    if (requested != SurfaceRaster::Auto) return requested == SurfaceRaster::Compute;
    for (const ComputeRasterRule& rule : kComputeRasterRule)
        if (renderer.find(rule.renderer) != std::string_view::npos)
            return double(triangles) >= rule.trianglesPerPixel * double(pixels);
    return false;
}

bool useComputeRaster(SurfaceRaster requested, size_t triangles, size_t pixels) {
    if (requested != SurfaceRaster::Auto) return requested == SurfaceRaster::Compute;
    return useComputeRaster(requested, currentRenderer(), triangles, pixels);
}

}  // namespace flowsurf::methods
