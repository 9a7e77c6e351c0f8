// flowsurf — the typed interface between C++ and GLSL: every enum value, limit and binding
// point a shader uses reaches it as a `#define` generated from the C++ definition (the
// enum name tables of params.h, the sizes of shader_limits.h, core::kNoiseMean, the
// table of gpu_bindings.h), so no number is copied by hand. Every program is built by
// `program()`, which prepends these definitions to its own variant defines.
#pragma once

#include "gl/objects.h"
#include "gpu/gpu_bindings.h"

#include <initializer_list>
#include <string>
#include <utility>

namespace flowsurf::methods {

// "#define NOISE_MEAN 0.5\n#define KERNEL_GAUSSIAN 2\n#define MAX_LEVELS 9\n..."
const std::string& shaderInterface();

// Work-group side of the per-pixel compute passes (PIXEL_GROUP in GLSL).
inline constexpr int kPixelGroup = 8;

// A per-pixel compute pass over a width x height image with the bound program, then the
// barrier that makes its image stores visible to what reads them next: textures, read-backs,
// framebuffer draws.
void dispatchPerPixel(int width, int height);

// Enables attribute `a` of `vao`: floats read from the buffer bound at a.buffer, a.offset
// floats into each vertex.
void enableAttribute(GLuint vao, const VertexAttribute& a);

// A linked program of the embedded `stages` with the interface and `defines` prepended.
gl::Program program(std::initializer_list<std::pair<GLenum, std::string>> stages, const std::string& defines = "");

}  // namespace flowsurf::methods
