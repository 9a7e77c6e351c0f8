// flowsurf — the resampling of F_a shared by ISA's and IBFVS's texture advection
// (shaders/image_space/resample.glsl): the shader variant for a Resample choice.
#pragma once

#include "params/params.h"

#include <string>

namespace flowsurf::methods {

// `#define`s to prepend to a program that includes image_space/resample.glsl.
inline std::string resampleDefine(Resample resample) {
    return resample == Resample::Bicubic ? "#define RESAMPLE_BICUBIC 1\n" : "";
}

}  // namespace flowsurf::methods
