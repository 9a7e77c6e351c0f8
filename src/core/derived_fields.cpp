// Sections: names · down and gradient · curvature tensors [Rusinkiewicz 2004] ·
// orientation of line fields · addDerivedField.
#include "core/derived_fields.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>
#include <sstream>

namespace flowsurf::core {

// --- names ------------------------------------------------------------------------------

bool isDerivedField(const std::string& name) {
    return isLineField(name) || name.rfind("gradient:", 0) == 0 || name.rfind("down:", 0) == 0;
}

bool isLineField(const std::string& name) { return name == "curvature-max" || name == "curvature-min"; }

namespace {

// --- down and gradient ------------------------------------------------------------------

glm::vec3 parseDirection(const std::string& text) {
    std::stringstream ss(text);
    glm::vec3 d(0.0f);
    char c1 = 0, c2 = 0, extra = 0;
    if (!(ss >> d.x >> c1 >> d.y >> c2 >> d.z) || c1 != ',' || c2 != ',' || (ss >> extra) || !std::isfinite(d.x) ||
        !std::isfinite(d.y) || !std::isfinite(d.z) || glm::length(d) == 0.0f)
        throw ConfigError("--field down:" + text + ": give a non-zero direction x,y,z (e.g. down:0,-1,0)");
    return d;
}

std::vector<glm::vec3> gradientOf(const SurfaceMesh& mesh, const std::vector<float>& f) {
    std::vector<glm::vec3> grad(mesh.vertexCount(), glm::vec3(0.0f));
    std::vector<float> weight(mesh.vertexCount(), 0.0f);
    for (const auto& t : mesh.triangles) {
        const glm::vec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
        const float v[3] = {f[t.x], f[t.y], f[t.z]};
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) continue;
        const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float n2 = glm::dot(n, n);
        if (n2 <= 0.0f) continue;
        // Linear interpolant's gradient: sum_i f_i (N x e_i) / |N|^2, e_i the edge opposite i.
        glm::vec3 g(0.0f);
        for (int i = 0; i < 3; ++i) g += v[i] * glm::cross(n, p[(i + 2) % 3] - p[(i + 1) % 3]);
        g /= n2;
        const float area = 0.5f * std::sqrt(n2);
        for (int i = 0; i < 3; ++i) {
            grad[t[i]] += area * g;
            weight[t[i]] += area;
        }
    }
    for (size_t i = 0; i < grad.size(); ++i)
        if (weight[i] > 0.0f) grad[i] /= weight[i];
    return grad;
}

// --- curvature tensors ------------------------------------------------------------------

// Rotates the frame (u, v) of normal nOld into the plane normal to nNew (the smallest
// rotation taking nOld to nNew).
void rotateFrame(glm::vec3& u, glm::vec3& v, const glm::vec3& nOld, const glm::vec3& nNew) {
    const float c = glm::dot(nOld, nNew);
    if (c <= -0.9999f) { u = -u; v = -v; return; }
    const glm::vec3 perp = nNew - c * nOld;
    const glm::vec3 dperp = (nOld + nNew) / (1.0f + c);
    u -= dperp * glm::dot(perp, u);
    v -= dperp * glm::dot(perp, v);
}

// Tensor (e, f, g) in frame (uFrom, vFrom) expressed in frame (uTo, vTo) of the same plane.
glm::vec3 reexpress(const glm::vec3& t, const glm::vec3& uFrom, const glm::vec3& vFrom, const glm::vec3& uTo,
                    const glm::vec3& vTo) {
    const float a = glm::dot(uTo, uFrom), b = glm::dot(uTo, vFrom);
    const float c = glm::dot(vTo, uFrom), d = glm::dot(vTo, vFrom);
    return {a * a * t.x + 2.0f * a * b * t.y + b * b * t.z, a * c * t.x + (a * d + b * c) * t.y + b * d * t.z,
            c * c * t.x + 2.0f * c * d * t.y + d * d * t.z};
}

void vertexFrame(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 a = std::abs(n.x) < 0.6f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(a - glm::dot(a, n) * n);
    v = glm::cross(n, u);
}

// (1) One face's second fundamental form (e, f, g) in its frame (uf, vf): least squares for
// II from dn = II e along the three edges. nullopt for a degenerate face.
std::optional<glm::vec3> faceTensor(const glm::vec3 (&p)[3], const glm::vec3 (&n)[3], const glm::vec3& uf,
                                    const glm::vec3& vf) {
    double m[3][3] = {}, r[3] = {};
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 e = p[(i + 2) % 3] - p[(i + 1) % 3], dn = n[(i + 2) % 3] - n[(i + 1) % 3];
        const double eu = glm::dot(e, uf), ev = glm::dot(e, vf), du = glm::dot(dn, uf), dv = glm::dot(dn, vf);
        // rows [eu ev 0] . (e f g) = du and [0 eu ev] . (e f g) = dv
        const double rows[2][3] = {{eu, ev, 0}, {0, eu, ev}}, rhs[2] = {du, dv};
        for (int k = 0; k < 2; ++k)
            for (int a = 0; a < 3; ++a) {
                r[a] += rows[k][a] * rhs[k];
                for (int b = 0; b < 3; ++b) m[a][b] += rows[k][a] * rows[k][b];
            }
    }
    // 3x3 normal equations by Cramer's rule
    auto det3 = [](double a[3][3]) {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double det = det3(m);
    if (std::abs(det) < 1e-30) return std::nullopt;
    double sol[3];
    for (int c = 0; c < 3; ++c) {
        double mc[3][3];
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) mc[a][b] = b == c ? r[a] : m[a][b];
        sol[c] = det3(mc) / det;
    }
    return glm::vec3{float(sol[0]), float(sol[1]), float(sol[2])};
}

// (3) The area-weighted mean of the tensors within `radius` of each vertex (reached along
// edges), each re-expressed in that vertex's frame.
std::vector<glm::vec3> smoothTensors(const SurfaceMesh& mesh, const std::vector<glm::vec3>& up,
                                     const std::vector<glm::vec3>& vp, const std::vector<glm::vec3>& tensor,
                                     const std::vector<float>& weight, float radius) {
    const size_t nv = mesh.vertexCount();
    std::vector<std::vector<uint32_t>> adj(nv);
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e) { adj[t[e]].push_back(t[(e + 1) % 3]); adj[t[(e + 1) % 3]].push_back(t[e]); }
    std::vector<glm::vec3> smooth(nv);
    std::vector<uint32_t> stamp(nv, UINT32_MAX), queue;
    for (uint32_t i = 0; i < nv; ++i) {
        glm::vec3 sum(0.0f);
        float wsum = 0.0f;
        queue.assign(1, i);
        stamp[i] = i;
        for (size_t q = 0; q < queue.size(); ++q) {
            const uint32_t j = queue[q];
            glm::vec3 u = up[j], v = vp[j];
            rotateFrame(u, v, mesh.normals[j], mesh.normals[i]);
            sum += weight[j] * reexpress(tensor[j], u, v, up[i], vp[i]);
            wsum += weight[j];
            for (uint32_t k : adj[j])
                if (stamp[k] != i && glm::length(mesh.positions[k] - mesh.positions[i]) <= radius) {
                    stamp[k] = i;
                    queue.push_back(k);
                }
        }
        smooth[i] = wsum > 0.0f ? sum / wsum : tensor[i];
    }
    return smooth;
}

}  // namespace

Curvature principalCurvatures(const SurfaceMesh& mesh, float radius) {
    const size_t nv = mesh.vertexCount();
    std::vector<glm::vec3> up(nv), vp(nv);
    for (size_t i = 0; i < nv; ++i) vertexFrame(mesh.normals[i], up[i], vp[i]);
    std::vector<glm::vec3> tensor(nv, glm::vec3(0.0f));  // (e, f, g) in (up, vp)
    std::vector<float> weight(nv, 0.0f);
    // (1) per face: the tensor in the face's frame
    for (const auto& t : mesh.triangles) {
        const glm::vec3 p[3] = {mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]};
        const glm::vec3 n[3] = {mesh.normals[t.x], mesh.normals[t.y], mesh.normals[t.z]};
        const glm::vec3 cr = glm::cross(p[1] - p[0], p[2] - p[0]);
        const float area = 0.5f * glm::length(cr);
        if (area <= 0.0f) continue;
        const glm::vec3 nf = cr / (2.0f * area);
        const glm::vec3 uf = glm::normalize(p[1] - p[0]), vf = glm::cross(nf, uf);
        const std::optional<glm::vec3> tf = faceTensor(p, n, uf, vf);
        if (!tf) continue;
        // (2) into each corner's vertex frame, weighted by a third of the face area
        for (int i = 0; i < 3; ++i) {
            glm::vec3 u = up[t[i]], v = vp[t[i]];
            rotateFrame(u, v, mesh.normals[t[i]], nf);
            tensor[t[i]] += area / 3.0f * reexpress(*tf, uf, vf, u, v);
            weight[t[i]] += area / 3.0f;
        }
    }
    for (size_t i = 0; i < nv; ++i)
        if (weight[i] > 0.0f) tensor[i] /= weight[i];
    // (3) optional smoothing over `radius`
    if (radius > 0.0f) tensor = smoothTensors(mesh, up, vp, tensor, weight, radius);
    // (4) eigen-decomposition of each 2x2 tensor
    Curvature c;
    c.k1.resize(nv), c.k2.resize(nv), c.dir1.resize(nv), c.dir2.resize(nv);
    for (size_t i = 0; i < nv; ++i) {
        const float e = tensor[i].x, f = tensor[i].y, g = tensor[i].z;
        const float mean = 0.5f * (e + g), dev = std::sqrt(0.25f * (e - g) * (e - g) + f * f);
        c.k1[i] = mean + dev;
        c.k2[i] = mean - dev;
        const float angle = 0.5f * std::atan2(2.0f * f, e - g);  // of the k1 direction from up
        c.dir1[i] = std::cos(angle) * up[i] + std::sin(angle) * vp[i];
        c.dir2[i] = glm::cross(mesh.normals[i], c.dir1[i]);
    }
    return c;
}

// --- orientation of line fields ---------------------------------------------------------

size_t orientLineField(std::vector<glm::vec3>& dirs, const std::vector<glm::uvec3>& triangles) {
    const size_t nv = dirs.size();
    std::vector<std::vector<uint32_t>> adj(nv);
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e) { adj[t[e]].push_back(t[(e + 1) % 3]); adj[t[(e + 1) % 3]].push_back(t[e]); }
    std::vector<char> done(nv, 0);
    using Item = std::pair<float, std::pair<uint32_t, uint32_t>>;  // |dot|, (from, to)
    for (uint32_t seed = 0; seed < nv; ++seed) {
        if (done[seed]) continue;
        done[seed] = 1;
        std::priority_queue<Item> heap;  // Prim's algorithm: most parallel neighbours first
        auto push = [&](uint32_t from) {
            for (uint32_t to : adj[from])
                if (!done[to]) heap.push({std::abs(glm::dot(dirs[from], dirs[to])), {from, to}});
        };
        push(seed);
        while (!heap.empty()) {
            const auto [from, to] = heap.top().second;
            heap.pop();
            if (done[to]) continue;
            done[to] = 1;
            if (glm::dot(dirs[from], dirs[to]) < 0.0f) dirs[to] = -dirs[to];
            push(to);
        }
    }
    size_t flips = 0;
    for (const auto& t : triangles)
        for (int e = 0; e < 3; ++e)
            if (t[e] < t[(e + 1) % 3] && glm::dot(dirs[t[e]], dirs[t[(e + 1) % 3]]) < 0.0f) ++flips;
    return flips;
}

// --- addDerivedField --------------------------------------------------------------------

void addDerivedField(SurfaceMesh& mesh, const std::string& name, const DerivedFieldOptions& options) {
    if (mesh.normals.size() != mesh.vertexCount()) mesh.normals = computeVertexNormals(mesh.positions, mesh.triangles);
    VectorField field{name, {}};
    if (name.rfind("down:", 0) == 0) {
        field.values.assign(mesh.vertexCount(), parseDirection(name.substr(5)));
        makeTangential(field.values, mesh.normals);
    } else if (name.rfind("gradient:", 0) == 0) {
        std::vector<float> f;
        if (!evalScalar(mesh, ScalarSpec::parse(name.substr(9)), f)) {
            std::string names;
            for (const auto& s : mesh.scalars) names += (names.empty() ? "" : ", ") + s.name;
            throw FieldError("--field " + name + ": no point scalar '" + name.substr(9) +
                             "' (available: " + (names.empty() ? "none" : names) + ")");
        }
        field.values = gradientOf(mesh, f);
        makeTangential(field.values, mesh.normals);
    } else if (isLineField(name)) {
        Curvature c = principalCurvatures(mesh, options.curvatureRadius);
        const bool max = name == "curvature-max";
        field.values = max ? c.dir1 : c.dir2;
        orientLineField(field.values, mesh.triangles);
        // Length: the anisotropy k1 - k2 (directions are undefined at umbilics and on planes).
        for (size_t i = 0; i < field.values.size(); ++i) field.values[i] *= c.k1[i] - c.k2[i];
    } else {
        throw ConfigError("--field " + name + ": not a derived field (curvature-max, curvature-min, gradient:ARRAY, "
                          "down:x,y,z)");
    }
    mesh.fields.push_back(std::move(field));
}

}  // namespace flowsurf::core
