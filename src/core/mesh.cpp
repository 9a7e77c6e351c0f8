#include "core/mesh.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace flowsurf::detail {
void checkFailed(const char* expr, const char* file, int line) {
    std::fprintf(stderr, "flowsurf: internal check failed: %s (%s:%d)\n", expr, file, line);
    std::abort();
}
}  // namespace flowsurf::detail

namespace flowsurf::core {

const VectorField* SurfaceMesh::findField(const std::string& name) const {
    for (const auto& f : fields)
        if (f.name == name) return &f;
    return nullptr;
}

const VectorField* SurfaceMesh::defaultField() const {
    for (const auto& f : fields)
        for (const auto& v : f.values)
            if (v != glm::vec3(0.0f)) return &f;
    return fields.empty() ? nullptr : &fields.front();
}

const ScalarField* SurfaceMesh::findScalar(const std::string& name) const {
    for (const auto& f : scalars)
        if (f.name == name) return &f;
    return nullptr;
}

ScalarSpec ScalarSpec::parse(const std::string& text) {
    ScalarSpec s;
    const auto colon = text.rfind(':');
    s.array = text;
    if (colon != std::string::npos) {
        const std::string c = text.substr(colon + 1);
        static const char* kNames[] = {"x", "y", "z", "mag"};
        int found = -2;
        for (int i = 0; i < 4; ++i)
            if (c == kNames[i]) found = i == 3 ? -1 : i;
        if (found == -2) throw ConfigError("'" + text + "': the component after ':' must be x, y, z or mag");
        s.array = text.substr(0, colon);
        s.component = found;
    }
    if (s.array.empty()) throw ConfigError("'" + text + "': no array name");
    return s;
}

std::string ScalarSpec::text() const {
    static const char* kNames[] = {"x", "y", "z"};
    return component < 0 ? array : array + ":" + kNames[component];
}

bool evalScalar(const SurfaceMesh& mesh, const ScalarSpec& spec, std::vector<float>& out) {
    if (const ScalarField* s = spec.component < 0 ? mesh.findScalar(spec.array) : nullptr) {
        out = s->values;
        return true;
    }
    const VectorField* v = mesh.findField(spec.array);
    if (!v) return false;
    out.resize(v->values.size());
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = spec.component < 0 ? glm::length(v->values[i]) : v->values[i][spec.component];
    return true;
}

std::pair<float, float> finiteRange(const std::vector<float>& values) {
    float lo = std::numeric_limits<float>::max(), hi = -std::numeric_limits<float>::max();
    for (float v : values)
        if (std::isfinite(v)) { lo = std::min(lo, v); hi = std::max(hi, v); }
    return {lo, hi};
}

Bounds SurfaceMesh::bounds() const {
    Bounds b;
    for (const auto& p : positions) b.extend(p);
    return b;
}

SurfaceMesh pieceOf(const SurfaceMesh& mesh, const std::function<bool(glm::vec3)>& keep) {
    SurfaceMesh p;
    p.units = mesh.units;
    std::unordered_map<uint32_t, uint32_t> index;  // mesh's vertex -> the piece's
    auto vertex = [&](uint32_t v) {
        auto [it, fresh] = index.try_emplace(v, uint32_t(p.positions.size()));
        if (fresh) {
            p.positions.push_back(mesh.positions[v]);
            if (v < mesh.normals.size()) p.normals.push_back(mesh.normals[v]);
        }
        return it->second;
    };
    for (const auto& t : mesh.triangles) {
        const glm::vec3 c = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0f;
        if (keep(c)) p.triangles.push_back({vertex(t.x), vertex(t.y), vertex(t.z)});
    }
    for (const auto& f : mesh.fields) {
        VectorField g{f.name, std::vector<glm::vec3>(p.positions.size())};
        for (auto [from, to] : index) g.values[to] = f.values[from];
        p.fields.push_back(std::move(g));
    }
    for (const auto& s : mesh.scalars) {
        ScalarField g{s.name, std::vector<float>(p.positions.size())};
        for (auto [from, to] : index) g.values[to] = s.values[from];
        p.scalars.push_back(std::move(g));
    }
    return p;
}

Bounds Dataset::bounds() const {
    Bounds b;
    for (const auto& s : steps) b.extend(s.mesh.bounds());
    return b;
}

std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<glm::uvec3>& triangles) {
    std::vector<glm::vec3> n(positions.size(), glm::vec3(0.0f));
    for (const auto& t : triangles) {
        // Cross product length = 2 * area: area weighting for free.
        glm::vec3 c = glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
        n[t.x] += c;
        n[t.y] += c;
        n[t.z] += c;
    }
    for (auto& v : n) {
        float l = glm::length(v);
        v = l > 0.0f ? v / l : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return n;
}

void makeTangential(std::vector<glm::vec3>& vectors, const std::vector<glm::vec3>& normals) {
    FLOWSURF_CHECK(vectors.size() == normals.size());
    for (size_t i = 0; i < vectors.size(); ++i)
        vectors[i] -= glm::dot(vectors[i], normals[i]) * normals[i];
}

namespace {
bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace

size_t validateMesh(SurfaceMesh& mesh, const std::string& where) {
    if (mesh.positions.empty()) throw FormatError(where + ": the surface has no points");
    if (mesh.triangles.empty()) throw FormatError(where + ": the surface has no triangles");
    const size_t n = mesh.positions.size();
    for (size_t i = 0; i < n; ++i)
        if (!finite3(mesh.positions[i])) {
            std::ostringstream s;
            s << where << ": point " << i << " has a non-finite coordinate (NaN or Inf)";
            throw FormatError(s.str());
        }
    if (!mesh.normals.empty() && mesh.normals.size() != n) {
        std::ostringstream s;
        s << where << ": " << mesh.normals.size() << " normals for " << n << " points";
        throw FormatError(s.str());
    }
    for (const auto& f : mesh.fields) {
        if (f.values.size() != n) {
            std::ostringstream s;
            s << where << ": field '" << f.name << "' has " << f.values.size() << " values for "
              << n << " points";
            throw FormatError(s.str());
        }
        for (size_t i = 0; i < n; ++i)
            if (!finite3(f.values[i])) {
                std::ostringstream s;
                s << where << ": field '" << f.name << "' has a non-finite vector (NaN or Inf) at point "
                  << i;
                throw FormatError(s.str());
            }
    }
    for (const auto& f : mesh.scalars)
        if (f.values.size() != n) {
            std::ostringstream s;
            s << where << ": scalar '" << f.name << "' has " << f.values.size() << " values for " << n << " points";
            throw FormatError(s.str());
        }
    std::vector<glm::uvec3> kept;
    kept.reserve(mesh.triangles.size());
    size_t degenerate = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri.x >= n || tri.y >= n || tri.z >= n) {
            std::ostringstream s;
            s << where << ": triangle " << t << " refers to point " << std::max({tri.x, tri.y, tri.z})
              << " but there are only " << n << " points";
            throw FormatError(s.str());
        }
        glm::vec3 c = glm::cross(mesh.positions[tri.y] - mesh.positions[tri.x],
                                 mesh.positions[tri.z] - mesh.positions[tri.x]);
        if (tri.x == tri.y || tri.y == tri.z || tri.x == tri.z || glm::dot(c, c) == 0.0f) {
            ++degenerate;
            continue;
        }
        kept.push_back(tri);
    }
    if (kept.empty())
        throw FormatError(where + ": all " + std::to_string(mesh.triangles.size()) +
                          " triangles are degenerate (zero area)");
    mesh.triangles.swap(kept);
    if (mesh.normals.empty()) mesh.normals = computeVertexNormals(mesh.positions, mesh.triangles);
    return degenerate;
}

}  // namespace flowsurf::core
