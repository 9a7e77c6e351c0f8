// flowsurf — a keyframed camera path: the camera of frame k, interpolated linearly
// between keyframes (eye, target, up, fov) and held before the first / after the last.
#pragma once

#include "core/camera.h"

#include <vector>

namespace flowsurf::core {

struct CameraKeyframe {
    int frame = 0;
    Camera camera;
};

class CameraPath {
public:
    CameraPath() = default;
    // Keyframes in any order; frames must be distinct. Throws ConfigError.
    explicit CameraPath(std::vector<CameraKeyframe> keyframes);
    bool empty() const { return keys_.empty(); }
    Camera at(int frame) const;

private:
    std::vector<CameraKeyframe> keys_;
};

}  // namespace flowsurf::core
