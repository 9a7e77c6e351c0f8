// flowsurf — what every subcommand does before rendering: load the data (file or
// builtin), pick the field and the time step, and set up the camera.
#pragma once

#include "core/camera.h"
#include "core/camera_path.h"
#include "core/mesh.h"
#include "core/time_series.h"
#include "io/dataset_reader.h"

#include <memory>
#include "session/options.h"

namespace flowsurf::session {

core::Dataset loadInput(const std::string& input);
// The input as time steps loaded on demand: builtin:NAME, a file, or a file series
// pattern (surf_%04d.vtp, surf_*.vtp); OpenFOAM's --patches and --foam-case applied.
std::unique_ptr<core::StepProvider> openInput(const RenderOptions& o);
std::unique_ptr<core::StepProvider> openInput(const std::string& input, const io::SourceOptions& options = {});
// The mesh of the requested step with its field selected; throws ConfigError/FieldError.
const core::SurfaceMesh& selectStep(const core::Dataset& data, size_t step);
// Camera from the options, or fitted to the bounds; clip planes always fitted.
// The data's axes for --up-axis 0/1/2 (x/y/z): up, right, and front (toward the
// default camera).
struct ViewFrame {
    glm::vec3 up, right, front;
};
ViewFrame viewFrame(int upAxis);
// From the target toward the eye for a --view preset ("" = the default view).
glm::vec3 viewDirection(const std::string& view, int upAxis);

core::Camera makeCamera(const RenderOptions& o, const core::Bounds& bounds);

// The camera of every frame: fixed, orbiting (--orbit), or keyframed (--camera-path).
class FrameCameras {
public:
    FrameCameras(const RenderOptions& o, const core::Bounds& bounds);
    core::Camera at(int frame) const;

private:
    core::Camera camera0_;
    float orbit_;
    core::CameraPath path_;
    core::Bounds bounds_;
};

}  // namespace flowsurf::session
