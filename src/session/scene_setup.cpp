#include "session/scene_setup.h"

#include "core/errors.h"

#include <algorithm>
#include "session/camera_path_file.h"

namespace flowsurf::session {

io::SourceOptions sourceOptions(const RenderOptions& o) {
    // skin-friction is derived in the reader process, from the volume only it reads.
    return io::SourceOptions{o.patches, o.foamCase, o.foamZeroTime, o.field == "skin-friction", o.viscosity};
}

ViewFrame viewFrame(int upAxis) {
    ViewFrame f;
    f.up = glm::vec3(0.0f);
    f.up[upAxis] = 1.0f;
    f.right = glm::vec3(0.0f);
    f.right[upAxis == 0 ? 1 : 0] = 1.0f;  // y-up: x; z-up: x; x-up: y
    f.front = glm::cross(f.right, f.up);   // y-up: +z; z-up: -y; x-up: -z
    return f;
}

glm::vec3 viewDirection(ViewPreset view, int upAxis) {
    const ViewFrame f = viewFrame(upAxis);
    using enum ViewPreset;
    switch (view) {
    case Default: return glm::normalize(0.45f * f.right + 0.35f * f.up + f.front);
    case Iso: return glm::normalize(f.right + f.up + f.front);
    // From the target toward the eye: against the direction the camera looks along.
    case PlusX: return {-1, 0, 0};
    case MinusX: return {1, 0, 0};
    case PlusY: return {0, -1, 0};
    case MinusY: return {0, 1, 0};
    case PlusZ: return {0, 0, -1};
    case MinusZ: return {0, 0, 1};
    }
    return -f.front;  // not reached: every preset is listed
}

core::Camera makeCamera(const RenderOptions& o, const core::Bounds& bounds) {
    // Default view: from the front, a little above and to the right (for the --up-axis);
    // a flat data set (a slice) is seen straight along its thin axis; --view presets as
    // ParaView's camera buttons.
    glm::vec3 dir = viewDirection(o.view, o.upAxis);
    const glm::vec3 extent = bounds.hi - bounds.lo;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (o.view == ViewPreset::Default)
        for (int a = 0; a < 3; ++a)
            if (extent[a] <= 0.02f * largest) {
                dir = glm::vec3(0.0f);
                dir[a] = 1.0f;
            }
    if (o.eye) dir = *o.eye - (o.target ? *o.target : bounds.center());
    core::Camera cam = core::fitCamera(bounds, o.size, dir, o.fov);
    if (o.view != ViewPreset::Default || o.upAxis != 1) {
        // Up is the data's up axis; seen along it, the front of the data faces down.
        const ViewFrame f = viewFrame(o.upAxis);
        const float along = glm::dot(glm::normalize(dir), f.up);
        cam.up = std::abs(along) > 0.95f ? (along > 0 ? -f.front : f.front) : f.up;
    }
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
