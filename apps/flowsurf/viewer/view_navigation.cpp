// flowsurf view — the mouse moves the camera: drag to rotate (turntable or trackball) or
// pan, wheel or right drag to zoom towards the cursor (view_state.h).
#include "view_state.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace flowsurf::app::view {

namespace {

glm::vec3 rotateAbout(const glm::vec3& v, const glm::vec3& axis, float radians) {
    return glm::angleAxis(radians, glm::normalize(axis)) * v;
}

}  // namespace

glm::vec2 ViewerState::cursorNdc(float x, float y) const {
    const core::Viewport v = viewSize();
    const int n = int(shownMethods().size());
    const int col = std::clamp(int(x) / v.width, 0, n - 1);
    const float lx = x - float(col * v.width);
    return {(lx + 0.5f) / float(v.width) * 2.0f - 1.0f, 1.0f - (y + 0.5f) / float(v.height) * 2.0f};
}

void ViewerState::mouseMove(float x, float y) {
    const glm::vec2 d = glm::vec2(x, y) - mouse_;
    mouse_ = {x, y};
    if (dragButton_.empty() || !haveData_ || (d.x == 0.0f && d.y == 0.0f)) return;
    takeOverCamera();
    core::Camera c = camera();
    glm::vec3 offset = c.eye - c.target;
    const glm::vec3 forward = glm::normalize(-offset);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 camUp = glm::cross(right, forward);
    const core::Viewport v = viewSize();
    if (dragPan_) {
        // The surface under the cursor follows it (exact at the target's depth).
        const float worldPerPx = c.orthographic() ? c.orthoHeight / float(v.height)
                                                  : 2.0f * glm::length(offset) *
                                                        std::tan(glm::radians(c.fovDeg) * 0.5f) / float(v.height);
        const glm::vec3 shift = (-d.x * right + d.y * camUp) * worldPerPx;
        c.eye += shift;
        c.target += shift;
    } else if (dragButton_ == "right") {
        // Zoom by dragging: 20 px up = one wheel step in.
        mouse_ = {x, y};
        scroll(-d.y / 20.0f);
        return;
    } else if (rotateMode == RotateMode::Turntable) {
        // Azimuth about the up axis, elevation about the screen's horizontal, kept off the poles.
        offset = rotateAbout(offset, turntableUp_, glm::radians(-d.x * kDegPerPixel));
        const glm::vec3 r = glm::normalize(glm::cross(-offset, turntableUp_));
        const float polar = std::acos(std::clamp(glm::dot(glm::normalize(offset), turntableUp_), -1.0f, 1.0f));
        const float wanted = std::clamp(polar + glm::radians(-d.y * kDegPerPixel), glm::radians(1.0f),
                                        glm::radians(179.0f));
        offset = rotateAbout(offset, r, wanted - polar);
        c.up = turntableUp_;
    } else {
        // Trackball: rotation about the screen axis perpendicular to the drag.
        const glm::vec3 omega = -glm::radians(kDegPerPixel) * (d.x * camUp + d.y * right);
        const float angle = glm::length(omega);
        if (angle > 0.0f) {
            offset = rotateAbout(offset, omega, angle);
            c.up = rotateAbout(camUp, omega, angle);
        }
    }
    c.eye = c.target + offset;
    setCamera(c);
}

void ViewerState::scroll(float steps) {
    if (!haveData_ || steps == 0.0f) return;
    takeOverCamera();
    core::Camera c = camera();
    const float f = std::pow(kZoomPerStep, steps);
    const glm::vec3 offset = c.eye - c.target;
    const glm::vec3 forward = glm::normalize(-offset);
    const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
    const glm::vec3 camUp = glm::cross(right, forward);
    const core::Viewport v = viewSize();
    const glm::vec2 ndc = cursorNdc(mouse_.x, mouse_.y);
    // The point under the cursor on the plane through the target stays under the cursor.
    if (c.orthographic()) {
        const float h = c.orthoHeight * 0.5f;
        const glm::vec3 p = c.target + ndc.x * h * v.aspect() * right + ndc.y * h * camUp;
        const glm::vec3 target = p + (c.target - p) * f;
        c.eye += target - c.target;
        c.target = target;
        c.orthoHeight *= f;
    } else {
        const float t = std::tan(glm::radians(c.fovDeg) * 0.5f);
        const glm::vec3 dir = glm::normalize(forward + ndc.x * t * v.aspect() * right + ndc.y * t * camUp);
        const glm::vec3 p = c.eye + dir * (glm::length(offset) / glm::dot(dir, forward));
        c.eye = p + (c.eye - p) * f;
        c.target = p + (c.target - p) * f;
    }
    setCamera(c);
}

}  // namespace flowsurf::app::view
