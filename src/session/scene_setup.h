// flowsurf — the camera every front end frames the data with (the options' camera, the
// --view presets and --up-axis, orbit and camera paths per frame), and how the options
// read the input.
#pragma once

#include "core/camera.h"
#include "core/camera_path.h"
#include "core/mesh.h"
#include "io/source_options.h"
#include "session/options/options.h"

#include <memory>

namespace flowsurf::session {

// How the options read a file made of parts (--patches, --foam-case): the options of
// io::openInput.
io::SourceOptions sourceOptions(const RenderOptions& o);
// Camera from the options, or fitted to the bounds; clip planes always fitted.
// The data's axes for --up-axis 0/1/2 (x/y/z): up, right, and front (toward the
// default camera).
struct ViewFrame {
    glm::vec3 up, right, front;
};
ViewFrame viewFrame(int upAxis);
// From the target toward the eye for a --view preset.
glm::vec3 viewDirection(ViewPreset view, int upAxis);

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
