// Colour by a scalar, the legend, warm-up and shape rendering (curvature directions on a
// torus): what a user sees.
#include "core/builtin_scenes.h"
#include "core/derived_fields.h"
#include "gl_test_util.h"
#include "methods/make_renderer.h"
#include "present/legend.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace flowsurf;

namespace {

// builtin:sphere with a point scalar "height" = y.
core::SurfaceMesh sphereWithHeight() {
    core::SurfaceMesh m = core::makeBuiltin("builtin:sphere").steps.front().mesh;
    core::ScalarField h{"height", {}};
    for (const auto& p : m.positions) h.values.push_back(p.y);
    m.scalars.push_back(h);
    return m;
}

test::Rendered render(const core::SurfaceMesh& mesh, const std::string& field, const methods::MethodParams& p,
                      const core::Viewport& vp, const core::Camera& cam, int frames, const std::string& method = "isa") {
    methods::SurfaceGpu surface(mesh, field, p.common);
    auto m = methods::makeMethod(method, p, vp);
    for (int k = 0; k <= frames; ++k) m->renderFrame({&surface, cam, uint32_t(k)});
    return test::readBack(*m, vp);
}

}  // namespace

// --color-by height --colormap gray --beta 0 (lighting off): the gray level is the height,
// seen from the front in orthographic projection: proportional to the pixel row.
TEST(ColorBy, GrayLevelFollowsTheScalar) {
    methods::MethodParams p;
    p.common.colorBy = "height";
    p.common.colormap = methods::Colormap::Gray;
    p.common.beta = 0.0f;
    p.common.lighting = false;
    const core::Viewport vp{128, 128};
    test::Rendered r = render(sphereWithHeight(), "velocity", p, vp, test::orthoFront(2.2f), 1);
    std::vector<double> gray, height;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            if (!r.onSurface(x, vp.height - 1 - y)) continue;
            gray.push_back(r.rgb[(size_t(y) * vp.width + x) * 3]);
            height.push_back(1.1 - 2.2 * (y + 0.5) / vp.height);  // top row = +1.1
        }
    const double c = test::pearson(gray, height);
    std::printf("correlation of gray level and height %.4f over %zu px\n", c, gray.size());
    EXPECT_GE(c, 0.98);
}

// The legend changes only the pixels of its box at the usual place (free: the sphere leaves
// room beside it), and many of them.
TEST(Legend, DrawnInItsBoxOnly) {
    methods::MethodParams p;
    p.common.colorBy = "height";
    const core::Viewport vp{256, 192};
    const core::SurfaceMesh mesh = sphereWithHeight();
    test::Rendered plain = render(mesh, "velocity", p, vp, test::orthoFront(3.6f), 3);
    p.common.legend = true;
    test::Rendered legend = render(mesh, "velocity", p, vp, test::orthoFront(3.6f), 3);
    const methods::RgbImage img = methods::makeLegendImage(p.common, {-1.0f, 1.0f}, "height", vp.height);
    const glm::ivec2 o = methods::legendOrigin(img, vp.width, vp.height);  // GL: bottom-left
    size_t inside = 0, outside = 0;
    for (int y = 0; y < vp.height; ++y)
        for (int x = 0; x < vp.width; ++x) {
            const size_t i = (size_t(y) * vp.width + x) * 3;
            const bool differs = plain.rgb[i] != legend.rgb[i] || plain.rgb[i + 1] != legend.rgb[i + 1] ||
                                 plain.rgb[i + 2] != legend.rgb[i + 2];
            const int glY = vp.height - 1 - y;
            const bool inBox = x >= o.x && x < o.x + img.width && glY >= o.y && glY < o.y + img.height;
            (inBox ? inside : outside) += differs ? 1 : 0;
        }
    std::printf("legend: %zu px changed in its %dx%d box, %zu outside\n", inside, img.width, img.height, outside);
    EXPECT_EQ(outside, 0u);
    EXPECT_GT(inside, size_t(img.height) * 4);
}

// After the default warm-up (3 / alpha frames) the texture has the contrast and the
// anisotropy of the steady state (frame 200), within 10 %.
TEST(Warmup, FirstWrittenFrameLooksConverged) {
    core::Dataset d = core::makeBuiltin("builtin:uniform-plane");
    methods::MethodParams p;
    p.common.noise.seed = 3;
    const int warm = int(std::ceil(3.0f / p.common.alpha));
    for (const char* method : {"isa", "ibfvs"}) {
        auto stats = [&](int frames) {
            test::Rendered r = test::renderScene(d, method, p, {192, 192}, test::orthoFront(2.2f), frames);
            double s = 0, s2 = 0;
            int n = 0;
            for (int y = 40; y < 152; ++y)
                for (int x = 40; x < 152; ++x) { s += r.f(x, y); s2 += r.f(x, y) * r.f(x, y); ++n; }
            const double sd = std::sqrt(std::max(0.0, s2 / n - (s / n) * (s / n)));
            const double aniso = test::correlationLength(r, 30, 30, 162, 162, 1, 0) /
                                 test::correlationLength(r, 30, 30, 162, 162, 0, 1);
            return std::make_pair(sd, aniso);
        };
        const auto first = stats(warm), last = stats(200);
        std::printf("%s: contrast %.4f vs %.4f, anisotropy %.2f vs %.2f\n", method, first.first, last.first,
                    first.second, last.second);
        EXPECT_NEAR(first.first / last.first, 1.0, 0.1) << method;
        EXPECT_NEAR(first.second / last.second, 1.0, 0.1) << method;
    }
}

// Shape rendering [L §V-B]: a torus about z seen from +z; its max-curvature direction is
// the tube's meridian, which projects radially. Streaks within 10 degrees, every method.
TEST(ShapeRendering, TorusStreaksFollowMaxCurvature) {
    core::SurfaceMesh torus = core::makeTorus({0, 0, 0}, 1.0f, 0.4f, 192, 64);
    for (auto& p : torus.positions) p = glm::vec3(p.x, -p.z, p.y);  // axis y -> z
    for (auto& n : torus.normals) n = glm::vec3(n.x, -n.z, n.y);
    core::addDerivedField(torus, "curvature-max");
    methods::MethodParams p;
    p.common.noise.seed = 5;
    const core::Viewport vp{256, 256};
    const core::Camera cam = test::orthoFront(3.0f);
    for (const char* method : {"isa", "ibfvs", "hybrid"}) {
        test::Rendered r = render(torus, "curvature-max", p, vp, cam, std::string(method) == "hybrid" ? 1 : 80, method);
        std::vector<float> errors;
        for (int y = 8; y < vp.height - 8; y += 6)
            for (int x = 8; x < vp.width - 8; x += 6) {
                const float cx = x + 0.5f - vp.width / 2.0f, cy = y + 0.5f - vp.height / 2.0f;
                const float rad = std::sqrt(cx * cx + cy * cy) * 3.0f / vp.height;  // object units
                if (rad < 0.7f || rad > 1.3f || !r.onSurface(x, y)) continue;  // the tube's top half
                const float expected = std::fmod(std::atan2(cy, cx) + glm::two_pi<float>(), glm::pi<float>());
                errors.push_back(test::orientationErrorDeg(test::streakOrientation(r, x, y, 4.0f), expected));
            }
        ASSERT_GT(errors.size(), 200u) << method;
        std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
        std::printf("%s: median streak angle to the max-curvature direction %.1f deg\n", method,
                    errors[errors.size() / 2]);
        EXPECT_LT(errors[errors.size() / 2], 10.0f) << method;
    }
}
