#include "skeleton/critical_points.h"

#include "skeleton/tangent_field.h"
#include "skeleton/parallel.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace flowsurf::skeleton {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

struct RawZero {
    glm::vec3 position;
    uint32_t triangle;
    uint32_t nearestVertex;
    int index;
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

float cross2(const glm::vec2& a, const glm::vec2& b) { return a.x * b.y - a.y * b.x; }

// (1) A triangle's zero: the winding number of its three vectors in its own plane (the
// normal on the vertex normals' side), and where the linear interpolant vanishes.
bool triangleZero(const SurfaceGraph& graph, const std::vector<glm::vec3>& f, const glm::uvec3& t, float tiny,
                  RawZero& out) {
    const glm::vec3 p[3] = {graph.positions[t.x], graph.positions[t.y], graph.positions[t.z]};
    glm::vec3 nt = glm::cross(p[1] - p[0], p[2] - p[0]);
    const float len = glm::length(nt);
    if (!(len > 0.0f)) return false;
    nt /= len;
    if (glm::dot(nt, graph.normals[t.x] + graph.normals[t.y] + graph.normals[t.z]) < 0.0f) nt = -nt;
    const glm::vec3 e1 = glm::normalize(p[1] - p[0]), e2 = glm::cross(nt, e1);
    // An (almost) zero vector is read as a tiny one along its vertex's own tangent frame axis,
    // the same in every triangle of the vertex, so a zero on a vertex is counted in exactly
    // one of its triangles.
    glm::vec2 v[3];
    for (int i = 0; i < 3; ++i) {
        glm::vec3 fi = f[t[i]];
        if (glm::length(fi) <= tiny) {
            glm::vec3 u, w;
            tangentFrame(graph.normals[t[i]], u, w);
            fi = tiny * glm::normalize(u + 0.6180339887f * w);  // off the grid's and frame's own axes
        }
        v[i] = {glm::dot(fi, e1), glm::dot(fi, e2)};
    }
    float turn = 0.0f;
    for (int i = 0; i < 3; ++i) {
        const glm::vec2 a = v[i], b = v[(i + 1) % 3];
        turn += std::atan2(cross2(a, b), glm::dot(a, b));
    }
    const int index = int(std::lround(turn / kTwoPi));
    if (index == 0) return false;
    // b1 (v1 - v0) + b2 (v2 - v0) = -v0
    const glm::vec2 d1 = v[1] - v[0], d2 = v[2] - v[0];
    const float det = cross2(d1, d2);
    glm::vec3 b(1.0f / 3.0f);
    if (std::abs(det) > 0.0f) {
        const float b1 = cross2(-v[0], d2) / det, b2 = cross2(d1, -v[0]) / det;
        b = glm::clamp(glm::vec3(1.0f - b1 - b2, b1, b2), 0.0f, 1.0f);
        b /= std::max(b.x + b.y + b.z, 1e-30f);
    }
    out.position = b.x * p[0] + b.y * p[1] + b.z * p[2];
    out.index = index;
    out.nearestVertex = t[b.x >= b.y && b.x >= b.z ? 0 : (b.y >= b.z ? 1 : 2)];
    return true;
}

}  // namespace

PointType classify(const glm::mat2& j, int index, float spiralRatio, glm::vec2 (&eigenvalues)[2]) {
    const float tr = j[0][0] + j[1][1], det = j[0][0] * j[1][1] - j[1][0] * j[0][1];
    const float disc = 0.25f * tr * tr - det;
    const float re = 0.5f * tr;
    if (disc >= 0.0f) {
        const float s = std::sqrt(disc);
        eigenvalues[0] = {re + s, 0.0f};
        eigenvalues[1] = {re - s, 0.0f};
    } else {
        const float im = std::sqrt(-disc);
        eigenvalues[0] = {re, im};
        eigenvalues[1] = {re, -im};
    }
    if (index < 0) return PointType::Saddle;
    const float im = std::abs(eigenvalues[0].y), absRe = std::abs(re);
    if (im <= spiralRatio * absRe) return re > 0.0f ? PointType::Source : PointType::Sink;
    if (absRe <= spiralRatio * im) return PointType::Center;
    return re > 0.0f ? PointType::RepellingFocus : PointType::AttractingFocus;
}

namespace {

// (1) every triangle's zero, in triangle order (the chunks are in order)
std::vector<RawZero> triangleZeros(const SurfaceGraph& graph, const std::vector<glm::vec3>& f, float tiny) {
    std::vector<std::vector<RawZero>> perThread(16);
    detail::parallelChunks(graph.triangles.size(), [&](size_t b, size_t e, size_t thread) {
        for (size_t i = b; i < e; ++i) {
            RawZero z;
            if (triangleZero(graph, f, graph.triangles[i], tiny, z)) {
                z.triangle = uint32_t(i);
                perThread[thread].push_back(z);
            }
        }
    });
    std::vector<RawZero> raw;
    for (const auto& part : perThread) raw.insert(raw.end(), part.begin(), part.end());
    return raw;
}

// (2) the slow regions: vertices under `slow`, joined along edges; a zero belongs to the slow
// region of its triangle's slowest vertex, else stands alone. The zeros of each group.
std::map<uint64_t, std::vector<size_t>> slowGroups(const SurfaceGraph& graph, const std::vector<glm::vec3>& f,
                                                   const std::vector<RawZero>& raw, float slow) {
    const size_t nv = graph.vertexCount();
    std::vector<uint32_t> parent(nv);
    std::iota(parent.begin(), parent.end(), 0u);
    auto isSlow = [&](uint32_t v) { return glm::length(f[v]) < slow; };
    for (uint32_t v = 0; v < nv; ++v) {
        if (!isSlow(v)) continue;
        for (uint32_t k = graph.neighbourStart[v]; k < graph.neighbourStart[v + 1]; ++k) {
            const uint32_t nb = graph.neighbours[k];
            if (nb < v || !isSlow(nb)) continue;
            const uint32_t a = findRoot(parent, v), b = findRoot(parent, nb);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);
        }
    }
    std::map<uint64_t, std::vector<size_t>> groups;
    for (size_t i = 0; i < raw.size(); ++i) {
        const glm::uvec3& t = graph.triangles[raw[i].triangle];
        uint32_t slowest = t.x;
        for (int k = 1; k < 3; ++k)
            if (glm::length(f[t[k]]) < glm::length(f[slowest])) slowest = t[k];
        const uint64_t key = isSlow(slowest) ? uint64_t(findRoot(parent, slowest)) : (uint64_t(1) << 40) + i;
        groups[key].push_back(i);
    }
    return groups;
}

// (3) a group's points: none where its zeros cancel, the one of the net index nearest the
// group's centre for +-1, else its parts as found (a higher-order zero); each typed by the
// Jacobian over the scale (or the group's extent).
void groupPoints(const SurfaceGraph& graph, const FieldOnGraph& field, const SkeletonParams& params,
                 const std::vector<RawZero>& raw, const std::vector<size_t>& members, std::vector<CriticalPoint>& points) {
    int net = 0;
    glm::vec3 centroid(0.0f);
    for (size_t m : members) {
        net += raw[m].index;
        centroid += raw[m].position;
    }
    if (net == 0) return;
    centroid /= float(members.size());
    std::vector<size_t> kept;
    if (std::abs(net) == 1) {
        size_t best = SIZE_MAX;
        float bestDist = 0.0f;
        for (size_t m : members) {
            if (raw[m].index != net) continue;
            const float d = glm::length(raw[m].position - centroid);
            if (best == SIZE_MAX || d < bestDist) { best = m; bestDist = d; }
        }
        if (best != SIZE_MAX) kept.push_back(best);
    } else {
        kept = members;
    }
    float extent = 0.0f;
    for (size_t m : members) extent = std::max(extent, glm::length(raw[m].position - centroid));
    for (size_t m : kept) {
        CriticalPoint cp;
        cp.position = raw[m].position;
        cp.index = raw[m].index;
        cp.merged = kept.size() == 1 ? members.size() : 1;
        const glm::mat2 j = meanJacobian(graph, field.jacobians, raw[m].nearestVertex, cp.position,
                                         std::max(field.scale, extent));
        cp.type = classify(j, cp.index, params.spiralRatio, cp.eigenvalues);
        points.push_back(cp);
    }
}

}  // namespace

std::vector<CriticalPoint> findCriticalPoints(const SurfaceGraph& graph, const FieldOnGraph& field,
                                              const SkeletonParams& params, size_t& zeros) {
    const std::vector<glm::vec3>& f = field.smoothed;
    const std::vector<RawZero> raw = triangleZeros(graph, f, 1e-7f * std::max(field.speed99, 1e-30f));
    zeros = raw.size();
    std::vector<CriticalPoint> points;
    for (const auto& [key, members] : slowGroups(graph, f, raw, params.cancelSpeed * field.speed99))
        groupPoints(graph, field, params, raw, members, points);
    return points;
}

}  // namespace flowsurf::skeleton
