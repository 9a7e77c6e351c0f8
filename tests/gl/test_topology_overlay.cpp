// --topology on over every method: the critical points drawn where they are, in their
// type's colour, hidden behind the surface, and no pixel changed away from them.
#include "core/builtin_scenes.h"
#include "core/time_series.h"
#include "methods/skeleton_layer/skeleton_layer.h"
#include "session/playback.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace flowsurf;

namespace {

// The unit sphere with the tangential part of +z: a source at the south pole, a sink at the
// north pole, seen from above (+z): the sink faces the camera, the source is behind.
core::Dataset poles() {
    core::SurfaceMesh m = core::makeUvSphere(1.0f, 48, 24);
    std::vector<glm::vec3> f;
    for (const glm::vec3& n : m.normals) f.push_back(glm::vec3(0, 0, 1) - n.z * n);
    m.fields = {{"velocity", f}};
    return {"poles", {{0.0, std::move(m)}}};
}

std::vector<uint8_t> render(const std::string& method, bool topology) {
    session::RenderOptions o;
    o.size = {96, 96};
    o.method = methods::kMethodNames.at(0).first;
    for (const auto& [value, name] : methods::kMethodNames)
        if (method == name) o.method = value;
    o.eye = glm::vec3(0, 0, 4);
    o.target = glm::vec3(0, 0, 0);
    o.up = glm::vec3(0, 1, 0);
    o.params.common.noise.seed = 7;
    o.topology = topology;
    o.topologyParts = "points";
    o.frames = 4;
    core::DatasetSteps steps(poles());
    session::Playback p(o);
    p.open(steps);
    p.still(o.frames);
    int w = 0, h = 0;
    return p.readImage(&w, &h);  // RGB, rows top to bottom
}

glm::vec3 colourAt(const std::vector<uint8_t>& rgb, int x, int y) {
    const size_t i = (size_t(y) * 96 + size_t(x)) * 3;
    return glm::vec3(rgb[i], rgb[i + 1], rgb[i + 2]) / 255.0f;
}

}  // namespace

TEST(TopologyOverlay, PointsDrawnWhereTheyAreHiddenBehindTheSurfaceTextureUntouchedElsewhere) {
    const glm::vec3 sink = methods::kPointStyles[size_t(skeleton::PointType::Sink)].colour;
    const glm::vec3 source = methods::kPointStyles[size_t(skeleton::PointType::Source)].colour;
    for (const char* method : {"isa", "ibfvs", "hybrid"}) {
        SCOPED_TRACE(method);
        const std::vector<uint8_t> off = render(method, false), on = render(method, true);
        ASSERT_EQ(off.size(), on.size());
        // the sink's glyph at the image centre, in its colour (a pixel of the fill)
        EXPECT_LT(glm::length(colourAt(on, 48, 48) - sink), 0.03f);
        EXPECT_GT(glm::length(colourAt(off, 48, 48) - sink), 0.03f);
        // the source behind the sphere: its colour nowhere; nothing changed beyond the glyph
        const float reach = 0.5f * session::RenderOptions{}.topologyGlyphSize + 3.0f;
        int changed = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) {
                EXPECT_GT(glm::length(colourAt(on, x, y) - source), 0.05f) << x << "," << y;
                const bool differs = colourAt(on, x, y) != colourAt(off, x, y);
                changed += differs;
                if (differs && std::hypot(x + 0.5f - 48.0f, y + 0.5f - 48.0f) > reach)
                    ADD_FAILURE() << "pixel " << x << "," << y << " changed away from the glyph";
            }
        EXPECT_GT(changed, 20);
    }
}
