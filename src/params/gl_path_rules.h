// flowsurf — the rules behind `--gl-path auto` and `--surface-raster auto` (GlPath,
// SurfaceRaster, params.h): which path is faster on which renderer, as plain data the
// option table prints and gpu/gl_path.h applies to the current GL context. No GL.
#pragma once

#include "params/params.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace flowsurf::methods {

// Mesa's software renderer, as its GL_RENDERER starts ("llvmpipe (LLVM 15.0.6, 256 bits)").
inline constexpr std::string_view kLlvmpipe = "llvmpipe";

// Renderer substring -> the faster path there, first match wins (doc/bench: fragment vs
// compute per stage). Anything unlisted takes the fragment path, the one every GL 4.5
// driver has run longest.
inline constexpr std::pair<std::string_view, GlPath> kAutoRule[] = {
    {"NVIDIA", GlPath::Compute},
    {kLlvmpipe, GlPath::Fragment},
};

// `requested` unless it is Auto; for Auto, the path measured to be faster on this kind of
// renderer (GL_RENDERER string): compute on NVIDIA's compute-centric parts, where graphics
// runs on a small part of the chip; kAutoRule above for the others.
inline GlPath glPathFor(GlPath requested, std::string_view renderer) {
    if (requested != GlPath::Auto) return requested;
    for (const auto& [name, path] : kAutoRule)
        if (renderer.find(name) != std::string_view::npos) return path;
    return GlPath::Fragment;
}

// What the auto rules read about a GL context's renderer, taken once per renderer object.
// The processes of a parallel group are taken to be alike (one renderer, the same
// LP_NUM_THREADS: `mpiexec -x LP_NUM_THREADS`), so they decide alike.
struct RendererInfo {
    std::string name;  // GL_RENDERER
    // The CPU cores a software renderer (llvmpipe) rasterises with: LP_NUM_THREADS when set
    // (at most the machine's CPUs), else the machine's CPUs; 0: a GPU.
    int cores = 0;
};

// Whether the surface passes rasterise with compute shaders (SurfaceRaster, params.h) for a
// surface of `triangles` drawn into `pixels`: as requested, or for Auto by the first rule of
// kComputeRasterRule whose renderer matches (and, for llvmpipe, whose cores do): compute from
// its triangles per pixel on.
// llvmpipe transforms, sets up and bins every triangle on one thread, while the visibility
// buffer spreads the triangles over all cores but pays a resolve per pixel. Crossover (ISA,
// dynamic frames, doc/bench/surface_raster_llvmpipe.txt), 2 cores: 0.30-0.45 triangles per
// pixel at 512^2, 0.43-0.57 at 1024^2; 1 core (ParaView's ranks, LP_NUM_THREADS=1 each):
// nothing to spread, GL faster up to 1.9 triangles per pixel for every method and at 2.9
// for ISA and the hybrid (1024^2), compute from 3.8 (AMD EPYC). NVIDIA's H100 and
// H200 run vertex and fragment work on a few graphics-capable units only, compute on all: at
// 1M triangles the visibility buffer wins from 0.48 triangles per pixel (1080p: hybrid 2.4 ->
// 1.4 ms, ISA 2.0 -> 1.0), GL at 0.12 (4K) (doc/bench/gpu_hopper.md). Other GPUs rasterise in
// fixed-function hardware: GL.
struct ComputeRasterRule {
    std::string_view renderer;  // GL_RENDERER substring
    int maxCores;               // the rule holds up to this many cores (RendererInfo::cores); 0: any
    double trianglesPerPixel;   // compute from this many triangles per pixel
};
inline constexpr ComputeRasterRule kComputeRasterRule[] = {
    {kLlvmpipe, 1, 3.0},
    {kLlvmpipe, 0, 0.5},
    {"H100", 0, 0.25},
    {"H200", 0, 0.25},
};

inline bool useComputeRaster(SurfaceRaster requested, const RendererInfo& renderer, size_t triangles, size_t pixels) {
    if (requested != SurfaceRaster::Auto) return requested == SurfaceRaster::Compute;
    for (const ComputeRasterRule& rule : kComputeRasterRule)
        if (renderer.name.find(rule.renderer) != std::string::npos && (rule.maxCores == 0 || renderer.cores <= rule.maxCores))
            return double(triangles) >= rule.trianglesPerPixel * double(pixels);
    return false;
}

}  // namespace flowsurf::methods
