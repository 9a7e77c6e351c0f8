#include "gpu/gl_path.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <utility>

namespace flowsurf::methods {

std::string_view currentRenderer() {
    const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return r ? std::string_view(r) : std::string_view();
}

GlPath resolveGlPath(GlPath requested) {
    if (requested != GlPath::Auto) return requested;
    return glPathFor(requested, currentRenderer());
}

RendererInfo currentRendererInfo() {
    RendererInfo info{std::string(currentRenderer()), 0};
    if (info.name.find(kLlvmpipe) == std::string::npos) return info;
    // Not the CPUs this process is bound to: how mpiexec binds its processes must not
    // change the image (the two paths differ by a fraction of a gray level).
    int cores = int(std::thread::hardware_concurrency());
    // LP_NUM_THREADS (llvmpipe's own variable; 0: it rasterises on the calling thread).
    if (const char* env = std::getenv("LP_NUM_THREADS")) {
        int threads = 0;
        const char* end = env + std::strlen(env);
        if (auto [ptr, ec] = std::from_chars(env, end, threads); ec == std::errc() && ptr == end && threads >= 0)
            cores = std::min(cores, std::max(threads, 1));
    }
    info.cores = std::max(cores, 1);
    return info;
}

bool useComputeRaster(SurfaceRaster requested, size_t triangles, size_t pixels) {
    if (requested != SurfaceRaster::Auto) return requested == SurfaceRaster::Compute;
    return useComputeRaster(requested, currentRendererInfo(), triangles, pixels);
}

}  // namespace flowsurf::methods
