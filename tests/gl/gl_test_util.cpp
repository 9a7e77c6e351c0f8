#include "gl_test_util.h"

#include "../common/autocorrelation.h"
#include "raster/surface_gpu.h"

#include "gl/readback.h"
#include "methods/make_renderer.h"
#include "quality/structure_tensor.h"

#include <glm/gtc/constants.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace flowsurf::test {

namespace {
// Debugging aid: FLOWSURF_TEST_DUMP=DIR writes each rendered result as PGM/PPM.
void dumpImages(const Rendered& r, const std::string& dir) {
    static int counter = 0;
    std::string base = dir + "/" + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                       std::to_string(counter++);
    if (FILE* f = std::fopen((base + "_flow.pgm").c_str(), "wb")) {
        std::fprintf(f, "P5 %d %d 255\n", r.width, r.height);
        for (int y = r.height - 1; y >= 0; --y)
            for (int x = 0; x < r.width; ++x) std::fputc(int(std::clamp(r.f(x, y), 0.0f, 1.0f) * 255.0f), f);
        std::fclose(f);
    }
    if (FILE* f = std::fopen((base + "_rgb.ppm").c_str(), "wb")) {
        std::fprintf(f, "P6 %d %d 255\n", r.width, r.height);
        std::fwrite(r.rgb.data(), 1, r.rgb.size(), f);
        std::fclose(f);
    }
}
}  // namespace

methods::MethodParams testParams() {
    methods::MethodParams p;
    p.common.noise.seed = 7;
    return p;
}

methods::MethodParams paperParams() {
    methods::MethodParams p = testParams();
    p.common.resample = methods::Resample::Bilinear;
    p.common.noiseInjection = methods::NoiseInjectionMode::Point;
    p.common.stepPx = 2.0f;
    return p;
}

Rendered readBack(const methods::FlowMethod& method, const core::Viewport& viewport) {
    Rendered r;
    r.width = viewport.width;
    r.height = viewport.height;
    r.flow = gl::readChannel(method.flowTexture(), 0);
    r.depth = gl::readDepth(method.surfaceDepth());
    r.rgb = gl::readRgb8TopDown(method.composite());
    return r;
}

Rendered renderScene(const core::Dataset& data, const std::string& method, const methods::MethodParams& params,
                     const core::Viewport& viewport, const core::Camera& camera, int frames) {
    methods::SurfaceGpu surface(data.steps.front().mesh, "velocity", params.common);
    auto m = methods::makeMethod(method, params, viewport);
    for (int k = 0; k <= frames; ++k) m->renderFrame({&surface, camera, uint32_t(k)});
    Rendered r = readBack(*m, viewport);
    if (const char* dir = std::getenv("FLOWSURF_TEST_DUMP")) dumpImages(r, dir);
    return r;
}

core::Camera orthoFront(float height) {
    core::Camera c;
    c.eye = {0, 0, 5};
    c.target = {0, 0, 0};
    c.up = {0, 1, 0};
    c.orthoHeight = height;
    c.nearPlane = 1.0f;
    c.farPlane = 9.0f;
    return c;
}

float correlationLength(const Rendered& r, int x0, int y0, int x1, int y1, int dx, int dy) {
    return autocorrelationLength([&](int x, int y) { return double(r.f(x, y)); }, x0, y0, x1, y1, dx, dy, 200, true);
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    const double n = double(a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        sa += a[i]; sb += b[i]; saa += a[i] * a[i]; sbb += b[i] * b[i]; sab += a[i] * b[i];
    }
    double cov = sab / n - sa / n * sb / n;
    double va = saa / n - sa / n * sa / n, vb = sbb / n - sb / n * sb / n;
    return cov / std::sqrt(std::max(va * vb, 1e-20));
}

float streakOrientation(const Rendered& r, int x, int y, float sigma) {
    return quality::streakAt({r.width, r.height, r.flow.data(), r.depth.data()}, x, y, sigma).angle;
}

float orientationErrorDeg(float a, float b) { return quality::orientationErrorDeg(a, b); }

}  // namespace flowsurf::test
