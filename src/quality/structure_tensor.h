// flowsurf — the structure tensor of a flow texture: the local streak direction and how
// coherent it is (doc/algorithms.md, "Quality metrics"). CPU, on a read-back image.
// Inputs: F_a and the window depth (1: background), rows bottom to top. No GL.
#pragma once

#include <cstddef>
#include <vector>

namespace flowsurf::quality {

// A read-back frame, not owned: F_a and the window depth (< 1 on the surface).
struct SurfaceImage {
    int width = 0, height = 0;
    const float* flow = nullptr;
    const float* depth = nullptr;
    bool onSurface(int x, int y) const { return depth[std::size_t(y) * width + x] < 1.0f; }
    float f(int x, int y) const { return flow[std::size_t(y) * width + x]; }
};

struct Streak {
    float angle = 0.0f;      // streak direction, radians in [0, pi), x right, y up
    float coherence = 0.0f;  // (l1 - l2) / (l1 + l2) of the tensor's eigenvalues, 0..1 (0: no gradient)
};

// The structure tensor at (x, y): central-difference gradients of F_a at pixels whose four
// neighbours are on the surface, products weighted by a Gaussian of `sigmaPx` (truncated
// at 2.5 sigma); the streaks run along its minor eigenvector.
Streak streakAt(const SurfaceImage& image, int x, int y, float sigmaPx);
// The same numbers at every pixel (separable filtering), rows bottom to top.
std::vector<Streak> streakField(const SurfaceImage& image, float sigmaPx);

// Smallest angle between two undirected orientations (radians), degrees in [0, 90].
float orientationErrorDeg(float a, float b);

}  // namespace flowsurf::quality
