// flowsurf — the resampling of F_a shared by ISA's and IBFVS's texture advection
// (shaders/common/resample.glsl): the shader variant for a Resample choice.
#pragma once

#include "methods/common/params.h"

#include <string>

namespace flowsurf::methods {

// `#define`s to prepend to a program that includes common/resample.glsl.
inline std::string resampleDefine(Resample resample) {
    return resample == Resample::Bicubic ? "#define RESAMPLE_BICUBIC 1\n" : "";
}

}  // namespace flowsurf::methods
