// The table of binding points and vertex attributes (gpu/gpu_bindings.h): the
// names the GLSL gets are distinct, and the surface vertex is packed as the buffer texture
// of the visibility pass reads it.
#include "gpu/gpu_bindings.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace flowsurf::methods;

TEST(GpuBindings, EveryGlslNameIsDefinedOnce) {
    std::set<std::string> names;
    size_t count = 0;
    auto add = [&](const std::string& name) {
        names.insert(name);
        ++count;
    };
    for (const BindingPoint& b : kBindingPoints) add(b.glsl);
    for (const BindingPoint& o : kFragmentOutputs) add(o.glsl);
    for (const VertexAttribute& a : kVertexAttributes) {
        add(std::string(a.glsl) + "_LOCATION");
        add(std::string(a.glsl) + "_OFFSET");
    }
    EXPECT_EQ(names.size(), count);
}

// The suffix says the kind, so a shader's layout qualifier reads as what it binds.
TEST(GpuBindings, NamesEndInTheirKind) {
    auto endsWith = [](const std::string& s, const std::string& end) {
        return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
    };
    for (const BindingPoint& b : kBindingPoints) {
        const std::string name = b.glsl;
        switch (b.kind) {
            case BindingPoint::Texture:
                EXPECT_TRUE(endsWith(name, "_UNIT") && !endsWith(name, "_IMAGE_UNIT")) << name;
                break;
            case BindingPoint::Image: EXPECT_TRUE(endsWith(name, "_IMAGE_UNIT")) << name; break;
            case BindingPoint::Storage: EXPECT_TRUE(endsWith(name, "_BINDING")) << name; break;
            case BindingPoint::Output: ADD_FAILURE() << name << ": an output among the binding points"; break;
        }
    }
    for (const BindingPoint& o : kFragmentOutputs) {
        EXPECT_EQ(o.kind, BindingPoint::Output) << o.glsl;
        EXPECT_TRUE(endsWith(o.glsl, "_OUT")) << o.glsl;
    }
}

TEST(GpuBindings, SurfaceVertexIsPackedInOrderIntoWholeTexels) {
    int next = 0;
    std::set<int> locations;
    for (const VertexAttribute& a : surface_vertex::kAttributes) {
        EXPECT_EQ(a.offset, next) << a.glsl;
        EXPECT_EQ(a.buffer, surface_vertex::kBuffer) << a.glsl;
        EXPECT_TRUE(locations.insert(a.location).second) << a.glsl;
        next = a.end();
    }
    // Position, normal, velocity (3 each), colour and mask value: 11 floats, one of padding.
    EXPECT_EQ(next, 11);
    EXPECT_EQ(surface_vertex::kFloats, 12);
    EXPECT_EQ(surface_vertex::kTexels, 3);
    EXPECT_EQ(surface_vertex::kStride, 48);
}

TEST(GpuBindings, LevelFieldsHaveTheirOwnLocationsAndBuffers) {
    // velocity_levels.vert reads them beside the surface's position and normal.
    for (const VertexAttribute& level : {kLevelFieldA, kLevelFieldB}) {
        EXPECT_NE(level.buffer, surface_vertex::kBuffer) << level.glsl;
        for (const VertexAttribute& a : surface_vertex::kAttributes) EXPECT_NE(level.location, a.location) << level.glsl;
    }
    EXPECT_NE(kLevelFieldA.location, kLevelFieldB.location);
    EXPECT_NE(kLevelFieldA.buffer, kLevelFieldB.buffer);
}
