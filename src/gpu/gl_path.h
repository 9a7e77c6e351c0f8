// flowsurf — the rules of params/gl_path_rules.h (`--gl-path auto`, `--surface-raster
// auto`) applied to the current GL context.
#pragma once

#include "params/gl_path_rules.h"

#include <cstddef>
#include <string_view>

namespace flowsurf::methods {

// The current GL context's GL_RENDERER ("" without one).
std::string_view currentRenderer();

// The same for the current GL context's renderer.
GlPath resolveGlPath(GlPath requested);

// What the auto rules read about the current GL context's renderer.
RendererInfo currentRendererInfo();

// useComputeRaster for the current context's renderer.
bool useComputeRaster(SurfaceRaster requested, size_t triangles, size_t pixels);

}  // namespace flowsurf::methods
