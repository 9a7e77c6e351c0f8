#include "core/builtin_scenes.h"

#include "core/errors.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace flowsurf::core {

namespace {

using FieldFn = std::function<glm::vec3(const glm::vec3& pos, double time)>;

void addField(SurfaceMesh& m, const FieldFn& fn, double time) {
    VectorField f{"velocity", {}};
    f.values.reserve(m.positions.size());
    for (const auto& p : m.positions) f.values.push_back(fn(p, time));
    makeTangential(f.values, m.normals);
    m.fields = {std::move(f)};
}

int gridForTriangles(long tris, int minimum) {
    return std::max(minimum, int(std::sqrt(double(tris) / 2.0)));
}

// Sphere in solid-body rotation about the axis (0.3, 1, 0.2): v = w x x.
Dataset sphereScene(long tris) {
    // slices n, stacks n/2: about n^2 triangles.
    int n = std::max(8, int(std::sqrt(double(tris > 0 ? tris : 40000))));
    SurfaceMesh m = makeUvSphere(1.0f, n, std::max(4, n / 2));
    glm::vec3 w = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    addField(m, [&](const glm::vec3& p, double) { return glm::cross(w, p); }, 0.0);
    return {"builtin:sphere", {{0.0, std::move(m)}}};
}

// Two tori under a uniform vertical field; only its tangential part remains [W Fig. 5].
Dataset toriScene(long tris) {
    int n = gridForTriangles(tris > 0 ? tris / 2 : 20000, 8);
    SurfaceMesh a = makeTorus({-1.2f, 0.0f, 0.0f}, 1.0f, 0.35f, n, std::max(6, n / 3));
    SurfaceMesh b = makeTorus({1.2f, 0.0f, 0.0f}, 1.0f, 0.35f, n, std::max(6, n / 3));
    // Tilt the second torus so both silhouettes and folds appear.
    for (auto* v : {&b.positions, &b.normals})
        for (auto& p : *v) {
            glm::vec3 q = v == &b.positions ? p - glm::vec3(1.2f, 0, 0) : p;
            q = {q.x, q.y * 0.5f - q.z * 0.866f, q.y * 0.866f + q.z * 0.5f};
            p = v == &b.positions ? q + glm::vec3(1.2f, 0, 0) : q;
        }
    appendMesh(a, b);
    addField(a, [](const glm::vec3&, double) { return glm::vec3(0, 1, 0); }, 0.0);
    return {"builtin:tori", {{0.0, std::move(a)}}};
}

// Oblique plane with a vortex (Rankine-like) plus a weak drift.
Dataset vortexPlaneScene(long tris) {
    int n = gridForTriangles(tris > 0 ? tris : 20000, 4);
    glm::vec3 u = glm::normalize(glm::vec3(1, 0, 0.4f)), v = glm::normalize(glm::vec3(0, 1, -0.5f));
    v = glm::normalize(v - glm::dot(v, u) * u);
    SurfaceMesh m = makeRectangle({0, 0, 0}, u, v, 4.0f, 3.0f, n, n * 3 / 4);
    addField(m, [&](const glm::vec3& p, double) {
        float x = glm::dot(p, u) - 0.4f, y = glm::dot(p, v) + 0.2f;
        float r2 = x * x + y * y, core = 0.6f;
        float s = r2 < core * core ? 1.0f / (core * core) : 1.0f / r2;  // solid core, 1/r outside
        return (-y * s) * u + (x * s) * v + 0.15f * u;
    }, 0.0);
    return {"builtin:vortex-plane", {{0.0, std::move(m)}}};
}

// Double gyre (Shadden et al.) on a plane: the classic time-dependent test field.
Dataset doubleGyreScene(long tris) {
    int n = gridForTriangles(tris > 0 ? tris : 20000, 4);
    const float A = 0.1f, eps = 0.25f, omega = glm::two_pi<float>() / 10.0f;
    Dataset d{"builtin:double-gyre", {}};
    SurfaceMesh base = makeRectangle({1, 0.5f, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, 1.0f, n, n / 2);
    for (int k = 0; k <= 10; ++k) {
        SurfaceMesh m = base;
        double t = k;
        addField(m, [&](const glm::vec3& p, double time) {
            float a = eps * std::sin(omega * float(time)), b = 1 - 2 * eps * std::sin(omega * float(time));
            float f = a * p.x * p.x + b * p.x, df = 2 * a * p.x + b;
            float pi = glm::pi<float>();
            return glm::vec3(-pi * A * std::sin(pi * f) * std::cos(pi * p.y),
                             pi * A * std::cos(pi * f) * std::sin(pi * p.y) * df, 0.0f);
        }, t);
        d.steps.push_back({t, std::move(m)});
    }
    return d;
}

// Uniform flow along x on a plane facing the camera: the correlation-length test.
Dataset uniformPlaneScene(long tris) {
    int n = gridForTriangles(tris > 0 ? tris : 2000, 2);
    SurfaceMesh m = makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, 2.0f, n, n);
    addField(m, [](const glm::vec3&, double) { return glm::vec3(1, 0, 0); }, 0.0);
    return {"builtin:uniform-plane", {{0.0, std::move(m)}}};
}

// Two overlapping planes at different depths with perpendicular flows: the front one
// covers the left half of the back one. The occluding-edge tests.
Dataset overlapPlanesScene(long tris) {
    int n = gridForTriangles(tris > 0 ? tris / 2 : 2000, 2);
    SurfaceMesh back = makeRectangle({0, 0, -1}, {1, 0, 0}, {0, 1, 0}, 2.0f, 2.0f, n, n);
    SurfaceMesh front = makeRectangle({-0.5f, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f, 2.0f, n / 2 + 1, n);
    addField(back, [](const glm::vec3&, double) { return glm::vec3(1, 0, 0); }, 0.0);
    addField(front, [](const glm::vec3&, double) { return glm::vec3(0, 1, 0); }, 0.0);
    appendMesh(back, front);
    return {"builtin:overlap-planes", {{0.0, std::move(back)}}};
}

// A plane facing +z whose uniform flow turns by 90 degrees over 8 time units: the
// texture must follow the field of the current data time, not the first step's.
Dataset turningPlaneScene(long tris) {
    int n = gridForTriangles(tris > 0 ? tris : 2000, 2);
    SurfaceMesh base = makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, 2.0f, n, n);
    Dataset d{"builtin:turning-plane", {}};
    for (int k = 0; k <= 8; ++k) {
        SurfaceMesh m = base;
        float a = glm::half_pi<float>() * float(k) / 8.0f;
        addField(m, [a](const glm::vec3&, double) { return glm::vec3(std::cos(a), std::sin(a), 0.0f); }, k);
        d.steps.push_back({double(k), std::move(m)});
    }
    return d;
}

// In the spirit of [L Fig. 11]: a cylinder (radius 1, head at z = 1) whose bottom, the
// piston, moves down and up over one cycle; the side wall is re-meshed every step with
// rings 0.1 apart, so its triangle count (the topology) changes with time. The flow is an
// intake-like swirl about the axis plus an axial part following the piston.
Dataset pistonScene(long tris) {
    const int slices = std::max(16, int(std::sqrt(double(tris > 0 ? tris : 8000) / 4.0)));
    const int steps = 24;
    Dataset d{"builtin:piston", {}};
    for (int k = 0; k <= steps; ++k) {
        const double t = double(k) / steps;  // one cycle
        const float bottom = -1.0f - 0.8f * float(0.5 * (1.0 - std::cos(glm::two_pi<double>() * t)));
        const float pistonSpeed = -0.8f * float(0.5 * glm::two_pi<double>() * std::sin(glm::two_pi<double>() * t));
        const int rings = std::max(2, int(std::ceil((1.0f - bottom) / 0.1f)));
        SurfaceMesh m;
        // Side wall, outward normals.
        for (int j = 0; j <= rings; ++j) {
            float z = bottom + (1.0f - bottom) * float(j) / float(rings);
            for (int i = 0; i < slices; ++i) {
                float a = glm::two_pi<float>() * float(i) / float(slices);
                glm::vec3 n(std::cos(a), std::sin(a), 0.0f);
                m.positions.push_back(n + glm::vec3(0, 0, z));
                m.normals.push_back(n);
            }
        }
        auto id = [&](int i, int j) { return uint32_t(j * slices + (i % slices)); };
        for (int j = 0; j < rings; ++j)
            for (int i = 0; i < slices; ++i) {
                m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        // Piston disc (a fan), normal up into the cylinder.
        uint32_t centre = uint32_t(m.positions.size());
        m.positions.push_back({0, 0, bottom});
        m.normals.push_back({0, 0, 1});
        uint32_t rim = uint32_t(m.positions.size());
        for (int i = 0; i < slices; ++i) {
            float a = glm::two_pi<float>() * float(i) / float(slices);
            m.positions.push_back({std::cos(a), std::sin(a), bottom});
            m.normals.push_back({0, 0, 1});
        }
        for (int i = 0; i < slices; ++i)
            m.triangles.push_back({centre, rim + uint32_t(i), rim + uint32_t((i + 1) % slices)});
        addField(m, [&](const glm::vec3& p, double) {
            glm::vec3 swirl = glm::vec3(-p.y, p.x, 0.0f) * (1.2f + 0.3f * p.z);
            float axial = pistonSpeed * (1.0f - p.z) / (1.0f - bottom);  // moves with the piston
            glm::vec3 radial = glm::vec3(p.x, p.y, 0.0f) * 0.6f * (p.z < bottom + 1e-4f ? 1.0f : 0.0f);
            return swirl + glm::vec3(0, 0, axial) + radial;
        }, t);
        d.steps.push_back({t, std::move(m)});
    }
    return d;
}

struct Entry {
    BuiltinInfo info;
    Dataset (*make)(long);
};
const std::vector<Entry>& entries() {
    static const std::vector<Entry> e = {
        {{"sphere", "unit sphere in solid-body rotation (steady)"}, sphereScene},
        {{"tori", "two tori under a uniform vertical field, tangential part (steady)"}, toriScene},
        {{"vortex-plane", "oblique plane with a vortex and a weak drift (steady)"}, vortexPlaneScene},
        {{"double-gyre", "time-dependent double gyre on a plane, 11 steps t=0..10"}, doubleGyreScene},
        {{"piston", "cylinder with a moving piston: geometry and topology change, swirl (25 steps)"}, pistonScene},
        {{"turning-plane", "plane whose uniform flow turns 90 degrees over 9 steps t=0..8"}, turningPlaneScene},
        {{"uniform-plane", "plane facing +z with uniform flow along x (tests)"}, uniformPlaneScene},
        {{"overlap-planes", "front plane over a back plane, perpendicular flows (tests)"}, overlapPlanesScene},
    };
    return e;
}

}  // namespace

const std::vector<BuiltinInfo>& builtinScenes() {
    static const std::vector<BuiltinInfo> list = [] {
        std::vector<BuiltinInfo> l;
        for (const auto& e : entries()) l.push_back(e.info);
        return l;
    }();
    return list;
}

bool isBuiltinSpec(const std::string& spec) { return spec.rfind("builtin:", 0) == 0; }

Dataset makeBuiltin(const std::string& spec) {
    std::string rest = spec.substr(8), name = rest;
    long tris = 0;
    if (auto colon = rest.find(':'); colon != std::string::npos) {
        name = rest.substr(0, colon);
        std::string count = rest.substr(colon + 1);
        char* end = nullptr;
        tris = std::strtol(count.c_str(), &end, 10);
        if (count.empty() || *end != '\0' || tris < 8 || tris > 20'000'000)
            throw ConfigError(spec + ": triangle count must be an integer in 8..20000000");
    }
    for (const auto& e : entries())
        if (e.info.name == name) {
            Dataset d = e.make(tris);
            d.source = spec;
            for (auto& s : d.steps) validateMesh(s.mesh, spec);
            return d;
        }
    std::string names;
    for (const auto& e : entries()) names += (names.empty() ? "" : ", ") + e.info.name;
    throw ConfigError("unknown built-in scene '" + name + "' (available: " + names + ")");
}

SurfaceMesh makeUvSphere(float radius, int slices, int stacks) {
    // Closed and welded: one vertex per pole, the seam shared, so every edge has two
    // triangles (the silhouette edge mask relies on it).
    SurfaceMesh m;
    auto add = [&](const glm::vec3& n) {
        m.positions.push_back(radius * n);
        m.normals.push_back(n);
    };
    add({0, 1, 0});
    for (int j = 1; j < stacks; ++j) {
        float theta = glm::pi<float>() * float(j) / float(stacks);
        for (int i = 0; i < slices; ++i) {
            float phi = glm::two_pi<float>() * float(i) / float(slices);
            add({std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
        }
    }
    add({0, -1, 0});
    const uint32_t south = uint32_t(m.positions.size() - 1);
    auto id = [&](int i, int j) { return uint32_t(1 + (j - 1) * slices + (i % slices)); };
    for (int i = 0; i < slices; ++i) {
        // Counter-clockwise seen from outside.
        m.triangles.push_back({0, id(i + 1, 1), id(i, 1)});
        m.triangles.push_back({south, id(i, stacks - 1), id(i + 1, stacks - 1)});
    }
    for (int j = 1; j < stacks - 1; ++j)
        for (int i = 0; i < slices; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
            m.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

SurfaceMesh makeTorus(const glm::vec3& center, float majorR, float minorR, int nu, int nv) {
    SurfaceMesh m;  // welded: indices wrap in both directions
    for (int j = 0; j < nv; ++j) {
        float b = glm::two_pi<float>() * float(j) / float(nv);
        for (int i = 0; i < nu; ++i) {
            float a = glm::two_pi<float>() * float(i) / float(nu);
            glm::vec3 ring(std::cos(a), 0.0f, std::sin(a));
            glm::vec3 n = std::cos(b) * ring + glm::vec3(0, std::sin(b), 0);
            m.positions.push_back(center + majorR * ring + minorR * n);
            m.normals.push_back(n);
        }
    }
    auto id = [&](int i, int j) { return uint32_t((j % nv) * nu + (i % nu)); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            m.triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
            m.triangles.push_back({id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)});
        }
    return m;
}

SurfaceMesh makeRectangle(const glm::vec3& center, const glm::vec3& u, const glm::vec3& v, float w,
                          float h, int n, int mcells) {
    SurfaceMesh m;
    glm::vec3 normal = glm::normalize(glm::cross(u, v));
    for (int j = 0; j <= mcells; ++j)
        for (int i = 0; i <= n; ++i) {
            float s = float(i) / float(n) - 0.5f, t = float(j) / float(mcells) - 0.5f;
            m.positions.push_back(center + s * w * u + t * h * v);
            m.normals.push_back(normal);
        }
    auto id = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < mcells; ++j)
        for (int i = 0; i < n; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

void appendMesh(SurfaceMesh& a, const SurfaceMesh& b) {
    uint32_t base = uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    for (auto t : b.triangles) a.triangles.push_back(t + glm::uvec3(base));
    for (size_t f = 0; f < a.fields.size() && f < b.fields.size(); ++f)
        a.fields[f].values.insert(a.fields[f].values.end(), b.fields[f].values.begin(),
                                  b.fields[f].values.end());
}

}  // namespace flowsurf::core
