// flowsurf — what every subcommand does before rendering: load the data (file or
// builtin), pick the field and the time step, and set up the camera.
#pragma once

#include "core/camera.h"
#include "core/mesh.h"
#include "options.h"

namespace flowsurf::app {

core::Dataset loadInput(const std::string& input);
// The mesh of the requested step with its field selected; throws ConfigError/FieldError.
const core::SurfaceMesh& selectStep(const core::Dataset& data, size_t step);
// Camera from the options, or fitted to the bounds; clip planes always fitted.
core::Camera makeCamera(const RenderOptions& o, const core::Bounds& bounds);

}  // namespace flowsurf::app
