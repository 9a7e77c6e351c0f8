#include "core/camera_path.h"

#include "core/errors.h"

#include <algorithm>

namespace flowsurf::core {

CameraPath::CameraPath(std::vector<CameraKeyframe> keyframes) : keys_(std::move(keyframes)) {
    std::sort(keys_.begin(), keys_.end(), [](const auto& a, const auto& b) { return a.frame < b.frame; });
    for (size_t i = 1; i < keys_.size(); ++i)
        if (keys_[i].frame == keys_[i - 1].frame)
            throw ConfigError("camera path: two keyframes at frame " + std::to_string(keys_[i].frame));
}

Camera CameraPath::at(int frame) const {
    if (keys_.empty()) return Camera{};
    if (frame <= keys_.front().frame) return keys_.front().camera;
    if (frame >= keys_.back().frame) return keys_.back().camera;
    auto next = std::upper_bound(keys_.begin(), keys_.end(), frame,
                                 [](int f, const CameraKeyframe& k) { return f < k.frame; });
    const CameraKeyframe& b = *next;
    const CameraKeyframe& a = *(next - 1);
    float t = float(frame - a.frame) / float(b.frame - a.frame);
    Camera c = a.camera;
    c.eye = glm::mix(a.camera.eye, b.camera.eye, t);
    c.target = glm::mix(a.camera.target, b.camera.target, t);
    c.up = glm::mix(a.camera.up, b.camera.up, t);
    c.fovDeg = glm::mix(a.camera.fovDeg, b.camera.fovDeg, t);
    c.orthoHeight = glm::mix(a.camera.orthoHeight, b.camera.orthoHeight, t);
    return c;
}

}  // namespace flowsurf::core
