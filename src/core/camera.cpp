#include "core/camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace flowsurf::core {

glm::mat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::mat4 Camera::projection(float aspect) const {
    if (orthographic()) {
        float h = 0.5f * orthoHeight, w = h * aspect;
        return glm::ortho(-w, w, -h, h, nearPlane, farPlane);
    }
    return glm::perspective(glm::radians(fovDeg), aspect, nearPlane, farPlane);
}

bool sameCamera(const Camera& a, const Camera& b) {
    return a.eye == b.eye && a.target == b.target && a.up == b.up && a.fovDeg == b.fovDeg &&
           a.orthoHeight == b.orthoHeight && a.nearPlane == b.nearPlane && a.farPlane == b.farPlane;
}

glm::vec3 projectToPixels(const Camera& camera, const Viewport& viewport, const glm::vec3& posObj) {
    glm::vec4 clip = camera.viewProjection(viewport.aspect()) * glm::vec4(posObj, 1.0f);
    glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * float(viewport.width), (ndc.y * 0.5f + 0.5f) * float(viewport.height),
            ndc.z * 0.5f + 0.5f};
}

Camera fitCamera(const Bounds& bounds, const Viewport& viewport, const glm::vec3& direction, float fovDeg) {
    Camera c;
    c.fovDeg = fovDeg;
    c.target = bounds.center();
    float r = std::max(bounds.radius(), 1e-6f);
    // The bounding sphere must fit the narrower of the two view angles.
    float halfV = glm::radians(fovDeg) * 0.5f;
    float halfH = std::atan(std::tan(halfV) * viewport.aspect());
    float half = std::min(halfV, halfH);
    float dist = r * 1.05f / std::sin(half);
    glm::vec3 dir = glm::normalize(direction);
    c.eye = c.target + dir * dist;
    c.up = std::abs(dir.y) > 0.95f ? glm::vec3(0, 0, dir.y > 0 ? -1 : 1) : glm::vec3(0, 1, 0);
    fitClipPlanes(c, bounds);
    // The sphere is conservative: move closer until the box corners fill the view
    // (largest |ndc| about 0.92), by bisection on the distance.
    auto extent = [&](const Camera& cam) {
        float m = 0.0f;
        glm::mat4 vp = cam.viewProjection(viewport.aspect());
        for (int i = 0; i < 8; ++i) {
            glm::vec3 p(i & 1 ? bounds.hi.x : bounds.lo.x, i & 2 ? bounds.hi.y : bounds.lo.y,
                        i & 4 ? bounds.hi.z : bounds.lo.z);
            glm::vec4 h = vp * glm::vec4(p, 1.0f);
            if (h.w <= 0.0f) return 1e9f;
            m = std::max({m, std::abs(h.x / h.w), std::abs(h.y / h.w)});
        }
        return m;
    };
    float lo = r * 0.2f, hi = dist;
    for (int it = 0; it < 24; ++it) {
        float mid = 0.5f * (lo + hi);
        Camera t = c;
        t.eye = c.target + dir * mid;
        fitClipPlanes(t, bounds);
        (extent(t) > 0.92f ? lo : hi) = mid;
    }
    c.eye = c.target + dir * hi;
    fitClipPlanes(c, bounds);
    return c;
}

void fitClipPlanes(Camera& camera, const Bounds& bounds) {
    float r = std::max(bounds.radius(), 1e-6f);
    glm::vec3 fwd = glm::normalize(camera.target - camera.eye);
    float dc = glm::dot(bounds.center() - camera.eye, fwd);
    float farP = dc + r * 1.01f;
    float nearP = dc - r * 1.01f;
    if (camera.orthographic()) {
        // Orthographic depth is linear: any near (even behind the eye) is fine.
        camera.nearPlane = nearP;
    } else {
        camera.nearPlane = std::max(nearP, farP * 1e-3f);
    }
    camera.farPlane = std::max(farP, camera.nearPlane + 1e-6f);
}

Camera orbitCamera(const Camera& camera, float degrees) {
    Camera c = camera;
    glm::mat4 rot = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::normalize(camera.up));
    c.eye = camera.target + glm::vec3(rot * glm::vec4(camera.eye - camera.target, 0.0f));
    return c;
}

float maxPixelsPerUnit(const Camera& camera, const Viewport& viewport, const Bounds& bounds,
                       std::span<const glm::vec3> samples) {
    if (camera.orthographic()) return float(viewport.height) / camera.orthoHeight;
    // The nearest box corner along the view axis bounds the scale of what is visible
    // (the bounding sphere would be far too pessimistic for flat domains).
    glm::vec3 fwd = glm::normalize(camera.target - camera.eye);
    float nearest = std::numeric_limits<float>::max();
    for (int i = 0; i < 8; ++i) {
        glm::vec3 p(i & 1 ? bounds.hi.x : bounds.lo.x, i & 2 ? bounds.hi.y : bounds.lo.y,
                    i & 4 ? bounds.hi.z : bounds.lo.z);
        nearest = std::min(nearest, glm::dot(p - camera.eye, fwd));
    }
    if (!samples.empty()) {
        // The nearest sample in the frustum (with a margin of a tenth of the view).
        const glm::vec3 right = glm::normalize(glm::cross(fwd, camera.up));
        const glm::vec3 up = glm::cross(right, fwd);
        const float tanY = 1.1f * std::tan(glm::radians(camera.fovDeg) * 0.5f);
        const float tanX = tanY * float(viewport.width) / float(viewport.height);
        float nearestSample = std::numeric_limits<float>::max();
        for (const glm::vec3& p : samples) {
            const glm::vec3 d = p - camera.eye;
            const float z = glm::dot(d, fwd);
            if (z > camera.nearPlane && std::abs(glm::dot(d, right)) <= z * tanX && std::abs(glm::dot(d, up)) <= z * tanY)
                nearestSample = std::min(nearestSample, z);
        }
        // Half its depth: a point between the samples may be nearer.
        if (nearestSample < std::numeric_limits<float>::max()) nearest = std::max(nearest, 0.5f * nearestSample);
    }
    nearest = std::max(nearest, camera.nearPlane);
    float viewHeight = 2.0f * nearest * std::tan(glm::radians(camera.fovDeg) * 0.5f);
    return float(viewport.height) / viewHeight;
}

}  // namespace flowsurf::core
