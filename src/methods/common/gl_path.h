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

// The same for the current GL context's renderer.
GlPath resolveGlPath(GlPath requested);

}  // namespace flowsurf::methods
