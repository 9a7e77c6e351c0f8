// flowsurf GL tests — rendering a scene with a method and measuring image properties
// (correlation lengths, structure-tensor orientation) on the read-back result.
#pragma once

#include "core/camera.h"
#include "core/mesh.h"
#include "methods/frame.h"

#include <cstdint>
#include <vector>

namespace flowsurf::test {

// While one lives, GL errors and high-severity debug messages do not fail the test (for
// tests that provoke them on purpose, e.g. an impossible allocation).
struct AllowGlErrors {
    AllowGlErrors();
    ~AllowGlErrors();
    AllowGlErrors(const AllowGlErrors&) = delete;
    AllowGlErrors& operator=(const AllowGlErrors&) = delete;
};

struct Rendered {
    int width = 0, height = 0;
    std::vector<float> flow;      // F_a, rows bottom to top
    std::vector<float> depth;     // window depth, rows bottom to top
    std::vector<uint8_t> rgb;     // composite RGB8, rows top to bottom
    bool onSurface(int x, int y) const { return depth[size_t(y) * width + x] < 1.0f; }
    float f(int x, int y) const { return flow[size_t(y) * width + x]; }
};

// The methods' defaults with the tests' fixed noise seed (7).
methods::MethodParams testParams();
// testParams with the paper's ISA/IBFVS settings [L]: bilinear resampling of F_a, noise
// sampled at the pixel, and the 2 px step that point-sampled noise of scale 2 px needs.
methods::MethodParams paperParams();

// Reads back the last frame of `method`: F_a, depth and the composite.
Rendered readBack(const methods::FlowMethod& method, const core::Viewport& viewport);

// Renders `frames` + 1 frames of `data` step 0 (field "velocity") with `method`.
Rendered renderScene(const core::Dataset& data, const std::string& method, const methods::MethodParams& params,
                     const core::Viewport& viewport, const core::Camera& camera, int frames);

// Orthographic camera looking down -z at the origin, view height `height`.
core::Camera orthoFront(float height);

// Autocorrelation length of F_a along (dx, dy) in pixels: the lag where the normalised
// autocorrelation over the box crosses 0.5 (linearly interpolated between lags).
float correlationLength(const Rendered& r, int x0, int y0, int x1, int y1, int dx, int dy);

// Pearson correlation of two equally long samples.
double pearson(const std::vector<double>& a, const std::vector<double>& b);

// Direction of the streaks at (x, y): the minor eigenvector of the structure tensor
// averaged with a Gaussian of `sigma` pixels; radians in [0, pi) (quality::streakAt).
float streakOrientation(const Rendered& r, int x, int y, float sigma);

// Smallest angle between two undirected orientations, degrees in [0, 90].
float orientationErrorDeg(float a, float b);

}  // namespace flowsurf::test
