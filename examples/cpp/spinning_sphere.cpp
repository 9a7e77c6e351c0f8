// Builds a sphere in solid-body rotation from plain arrays, renders it with the hybrid
// LIC, and writes a PNG:   spinning_sphere OUT.png [METHOD]
#include <flowsurf/flowsurf.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUT.png [isa|ibfvs|hybrid]\n", argv[0]);
        return 2;
    }
    // A UV sphere: points, triangles, and the velocity w x p of a rotation about w.
    const int rings = 48, segments = 96;
    const float w[3] = {0.3f, 1.0f, 0.2f};
    std::vector<float> points, vectors;
    std::vector<uint32_t> triangles;
    for (int i = 0; i <= rings; ++i)
        for (int j = 0; j <= segments; ++j) {
            const float theta = 3.14159265f * i / rings, phi = 6.2831853f * j / segments;
            const float p[3] = {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)};
            points.insert(points.end(), p, p + 3);
            vectors.insert(vectors.end(), {w[1] * p[2] - w[2] * p[1], w[2] * p[0] - w[0] * p[2], w[0] * p[1] - w[1] * p[0]});
        }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const uint32_t a = i * (segments + 1) + j, b = a + segments + 1;
            triangles.insert(triangles.end(), {a, b, a + 1, a + 1, b, b + 1});
        }
    try {
        flowsurf::Surface sphere = flowsurf::Surface::fromArrays(points.data(), points.size() / 3, triangles.data(),
                                                                 triangles.size() / 3, vectors.data());
        flowsurf::Renderer renderer;  // its own headless OpenGL context
        renderer.set("method", argc > 2 ? argv[2] : "hybrid");
        renderer.set("size", "480x360");
        renderer.render(sphere, 60);
        std::vector<uint8_t> rgb(size_t(renderer.width()) * renderer.height() * 3);
        renderer.readImage(rgb.data());
        flowsurf::writePng(argv[1], renderer.width(), renderer.height(), rgb.data());
        for (const auto& [stage, ms] : renderer.stageMs()) std::printf("%-20s %6.2f ms\n", stage.c_str(), ms);
        std::printf("wrote %s (%s)\n", argv[1], renderer.glRenderer().c_str());
    } catch (const flowsurf::Error& e) {
        std::fprintf(stderr, "spinning_sphere: %s\n", e.what());
        return 1;
    }
    return 0;
}
