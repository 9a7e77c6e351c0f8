// flowsurf — reading `--camera-path FILE` (JSON, parsed with nlohmann/json):
//   {"keyframes": [{"frame": 0, "eye": [x,y,z], "target": [x,y,z], "up": [0,1,0], "fov": 30}, ...]}
// "target", "up" and "fov" are optional (default: the fitted camera's).
#pragma once

#include "core/camera_path.h"

#include <string>

namespace flowsurf::session {

// Throws IoError (cannot open) or FormatError naming the file and the keyframe.
core::CameraPath readCameraPath(const std::string& path, const core::Camera& defaults);

}  // namespace flowsurf::session
