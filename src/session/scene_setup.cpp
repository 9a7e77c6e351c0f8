#include "session/scene_setup.h"

#include "core/builtin_scenes.h"
#include "core/errors.h"

#include <algorithm>
#include "session/camera_path_file.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"

namespace flowsurf::session {

core::Dataset loadInput(const std::string& input) {
    if (core::isBuiltinSpec(input)) return core::makeBuiltin(input);
    return io::readDataset(input);
}

std::unique_ptr<core::StepProvider> openInput(const std::string& input) {
    if (core::isBuiltinSpec(input)) return std::make_unique<core::DatasetSteps>(core::makeBuiltin(input));
    return io::openSeries(input);
}

const core::SurfaceMesh& selectStep(const core::Dataset& data, size_t step) {
    if (step >= data.steps.size())
        throw ConfigError("--time-step " + std::to_string(step) + ": " + data.source + " has " +
                          std::to_string(data.steps.size()) + " time step(s)");
    return data.steps[step].mesh;
}

core::Camera makeCamera(const RenderOptions& o, const core::Bounds& bounds) {
    // Default view: from the front, a little above and to the right; a flat data set (a
    // slice) is seen straight along its thin axis.
    glm::vec3 dir = glm::normalize(glm::vec3(0.45f, 0.35f, 1.0f));
    const glm::vec3 extent = bounds.hi - bounds.lo;
    const float largest = std::max({extent.x, extent.y, extent.z});
    for (int a = 0; a < 3; ++a)
        if (extent[a] <= 0.02f * largest) {
            dir = glm::vec3(0.0f);
            dir[a] = 1.0f;
        }
    if (o.eye) dir = *o.eye - (o.target ? *o.target : bounds.center());
    core::Camera cam = core::fitCamera(bounds, o.size, dir, o.fov);
    if (o.eye) cam.eye = *o.eye;
    if (o.target) cam.target = *o.target;
    if (o.up) cam.up = glm::normalize(*o.up);
    cam.orthoHeight = o.ortho;
    if (cam.orthographic() && !o.eye) cam.eye = cam.target + glm::normalize(dir) * bounds.radius() * 3.0f;
    if (glm::length(glm::cross(glm::normalize(cam.target - cam.eye), cam.up)) < 1e-4f)
        throw ConfigError("--up is parallel to the viewing direction");
    core::fitClipPlanes(cam, bounds);
    return cam;
}

FrameCameras::FrameCameras(const RenderOptions& o, const core::Bounds& bounds)
    : camera0_(makeCamera(o, bounds)), orbit_(o.orbit), bounds_(bounds) {
    if (!o.cameraPath.empty()) path_ = readCameraPath(o.cameraPath, camera0_);
}

core::Camera FrameCameras::at(int frame) const {
    if (path_.empty()) return core::orbitCamera(camera0_, orbit_ * float(frame));
    core::Camera c = path_.at(frame);
    core::fitClipPlanes(c, bounds_);
    return c;
}

}  // namespace flowsurf::session
