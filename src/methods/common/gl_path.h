// flowsurf — which GL stage runs the per-pixel passes (GlPath, params.h): the rule behind
// `--gl-path auto`, in one place.
#pragma once

#include "methods/common/params.h"

#include <string_view>

namespace flowsurf::methods {

// `requested` unless it is Auto; for Auto, the path measured to be faster on this kind of
// renderer (GL_RENDERER string): compute on NVIDIA's compute-centric parts, where graphics
// runs on a small part of the chip; see the table in gl_path.cpp for the others.
GlPath glPathFor(GlPath requested, std::string_view renderer);

// The current GL context's GL_RENDERER ("" without one).
std::string_view currentRenderer();

// The same for the current GL context's renderer.
GlPath resolveGlPath(GlPath requested);

// Whether the surface passes rasterise with compute shaders (SurfaceRaster, params.h) for a
// surface of `triangles` drawn into `pixels`: as requested, or for Auto where the renderer
// is listed in kComputeRasterRule and triangles >= its triangles per pixel x pixels.
// llvmpipe transforms, sets up and bins every triangle on one thread, while the visibility
// buffer spreads the triangles over all cores but pays a resolve per pixel. Crossover (ISA,
// dynamic frames, doc/bench/surface_raster_llvmpipe.txt): 0.30-0.45 triangles per pixel at
// 512^2, 0.43-0.57 at 1024^2. NVIDIA's H100 and H200 run vertex and fragment work on a few
// graphics-capable units only, compute on all: at 1M triangles the visibility buffer wins
// from 0.48 triangles per pixel (1080p: hybrid 2.4 -> 1.4 ms, ISA 2.0 -> 1.0), GL at 0.12
// (4K) (doc/bench/gpu_hopper.md). Other GPUs rasterise in fixed-function hardware: GL.
struct ComputeRasterRule {
    std::string_view renderer;  // GL_RENDERER substring
    double trianglesPerPixel;   // compute from this many triangles per pixel
};
inline constexpr ComputeRasterRule kComputeRasterRule[] = {
    {"llvmpipe", 0.5},
    {"H100", 0.25},
    {"H200", 0.25},
};
bool useComputeRaster(SurfaceRaster requested, std::string_view renderer, size_t triangles, size_t pixels);
bool useComputeRaster(SurfaceRaster requested, size_t triangles, size_t pixels);  // current context

}  // namespace flowsurf::methods
