// flowsurf — the typed interface between C++ and GLSL: every enum value and limit a
// shader compares against reaches it as a `#define` generated from the C++ definition
// (the enum name tables of params.h, TimeLevelSource::kMaxLevels, core::kNoiseMean), so
// no number is copied by hand. Every program of the methods is built by `program()`,
// which prepends these definitions to its own variant defines.
#pragma once

#include "gl/objects.h"

#include <initializer_list>
#include <string>
#include <utility>

namespace flowsurf::methods {

// "#define NOISE_MEAN 0.5\n#define KERNEL_GAUSSIAN 2\n#define MAX_LEVELS 9\n..."
const std::string& shaderInterface();

// Work-group side of the per-pixel compute passes (PIXEL_GROUP in GLSL).
inline constexpr int kPixelGroup = 8;

// Contrast enhancement [issue 28]: the histogram's storage buffer binding and the texture
// units of the stretch pass (HISTOGRAM_BINDING, CONTRAST_FLOW_UNIT, CONTRAST_DEPTH_UNIT).
inline constexpr int kHistogramBinding = 8;  // SSBO, apart from the dye and visibility ones
inline constexpr int kContrastFlowUnit = 0;
inline constexpr int kContrastDepthUnit = 1;

// A per-pixel compute pass over a width x height image with the bound program, then the
// barrier that makes its image stores visible to what reads them next: textures, read-backs,
// framebuffer draws.
void dispatchPerPixel(int width, int height);

// A linked program of the embedded `stages` with the interface and `defines` prepended.
gl::Program program(std::initializer_list<std::pair<GLenum, std::string>> stages, const std::string& defines = "");

}  // namespace flowsurf::methods
