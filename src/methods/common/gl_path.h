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
// surface of `triangles` drawn into `pixels`: as requested, or for Auto on a software
// renderer (llvmpipe) when triangles >= kComputeRasterTrianglesPerPixel x pixels. There GL
// transforms, sets up and bins every triangle on one thread, while the visibility buffer
// spreads the triangles over all cores but pays a resolve per pixel. Crossover (ISA, dynamic
// frames, doc/bench/surface_raster_llvmpipe.txt): 0.30-0.45 triangles per pixel at 512^2,
// 0.43-0.57 at 1024^2. GPUs rasterise in fixed-function hardware: GL.
inline constexpr double kComputeRasterTrianglesPerPixel = 0.5;
bool useComputeRaster(SurfaceRaster requested, std::string_view renderer, size_t triangles, size_t pixels);
bool useComputeRaster(SurfaceRaster requested, size_t triangles, size_t pixels);  // current context

}  // namespace flowsurf::methods
