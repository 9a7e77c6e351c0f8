// flowsurf — camera and the projection T(x) of §0: model-view-projection, homogeneous
// division and viewport map, object space -> image (device) pixels. No GL here.
#pragma once

#include "core/mesh.h"

#include <glm/glm.hpp>

#include <span>

namespace flowsurf::core {

// The image sizes every front end accepts, each side in pixels.
inline constexpr int kMinImageSide = 16;
inline constexpr int kMaxImageSide = 8192;

struct Viewport {
    int width = 512;   // pixels
    int height = 512;  // pixels
    float aspect() const { return float(width) / float(height); }
};

struct Camera {
    glm::vec3 eye{0.0f, 0.0f, 5.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovDeg = 30.0f;      // vertical field of view, perspective only
    float orthoHeight = 0.0f;  // > 0: orthographic with this view height (object units)
    float nearPlane = 0.1f;    // object units
    float farPlane = 100.0f;   // object units

    bool orthographic() const { return orthoHeight > 0.0f; }
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    glm::mat4 viewProjection(float aspect) const { return projection(aspect) * view(); }
};

// Exact equality of every camera parameter (the static case needs "nothing changed").
bool sameCamera(const Camera& a, const Camera& b);

// T(x): object space -> (x px, y px, window depth in [0,1]); pixel origin bottom-left,
// pixel centres at half-integers, as OpenGL rasterises.
glm::vec3 projectToPixels(const Camera& camera, const Viewport& viewport, const glm::vec3& posObj);

// A camera that looks at the bounds from `direction` (from the target towards the eye)
// and fits them in the view with a small margin.
Camera fitCamera(const Bounds& bounds, const Viewport& viewport, const glm::vec3& direction,
                 float fovDeg = 30.0f);

// Sets near/far tightly around the bounds (better depth precision for edge detection).
void fitClipPlanes(Camera& camera, const Bounds& bounds);

// Turns the eye about the target around the up axis by `degrees` (the --orbit path).
Camera orbitCamera(const Camera& camera, float degrees);

// Upper bound of the image scale (pixels per object unit) of what is visible: used to turn
// a step given in pixels into dt. Perspective: the scale at the depth of the bounds' nearest
// corner, or, when `samples` (points on the surface) are given and the nearest of them in
// the view frustum is more than twice as deep, at half that depth: a camera close to or
// inside the bounds, whose nearest corner is off screen or behind it. Never nearer than the
// near plane.
float maxPixelsPerUnit(const Camera& camera, const Viewport& viewport, const Bounds& bounds,
                       std::span<const glm::vec3> samples = {});

}  // namespace flowsurf::core
