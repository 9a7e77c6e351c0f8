#include "skeleton/surface_graph.h"

#include "skeleton/parallel.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace flowsurf::skeleton {

namespace {

struct CellKey {
    int64_t x, y, z;
    bool operator==(const CellKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct CellHash {
    size_t operator()(const CellKey& k) const {
        // splitmix64's finaliser over the three coordinates
        uint64_t h = uint64_t(k.x) * 0x9E3779B97F4A7C15ull ^ uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full ^
                     uint64_t(k.z) * 0x165667B19E3779F9ull;
        h ^= h >> 30;
        h *= 0xBF58476D1CE4E5B9ull;
        h ^= h >> 27;
        h *= 0x94D049BB133111EBull;
        return size_t(h ^ (h >> 31));
    }
};

// A grid coordinate, clamped so that no tolerance makes the conversion overflow.
int64_t cellOf(float x, double cell) {
    return int64_t(std::clamp(std::floor(double(x) / cell), -4.0e18, 4.0e18));
}

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// Each vertex's neighbours once, sorted, with how many triangles share that edge (1: a
// boundary edge, above 2: non-manifold): counted per vertex rather than by sorting every
// edge, so the memory is one entry per triangle corner and side (6 F), compacted in place.
struct Adjacency {
    std::vector<uint32_t> start, neighbours;
    std::vector<uint8_t> sharing;  // per entry, capped at 255
};

Adjacency adjacencyOf(size_t nv, const std::vector<glm::uvec3>& triangles) {
    Adjacency a;
    a.start.assign(nv + 1, 0);
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) a.start[t[k] + 1] += 2;
    for (size_t v = 0; v < nv; ++v) a.start[v + 1] += a.start[v];
    a.neighbours.resize(a.start[nv]);
    {
        std::vector<uint32_t> fill(a.start.begin(), a.start.end() - 1);
        for (const glm::uvec3& t : triangles)
            for (int k = 0; k < 3; ++k) {
                const uint32_t x = t[k], y = t[(k + 1) % 3];
                a.neighbours[fill[x]++] = y;
                a.neighbours[fill[y]++] = x;
            }
    }
    // per vertex: sort, keep each neighbour once with its count (at the front of its range)
    a.sharing.assign(a.neighbours.size(), 0);
    std::vector<uint32_t> unique(nv, 0);
    detail::parallelFor(nv, [&](size_t v) {
        const auto b = a.neighbours.begin() + a.start[v], e = a.neighbours.begin() + a.start[v + 1];
        std::sort(b, e);
        uint32_t out = a.start[v];
        for (uint32_t i = a.start[v]; i < a.start[v + 1];) {
            uint32_t j = i;
            while (j < a.start[v + 1] && a.neighbours[j] == a.neighbours[i]) ++j;
            a.neighbours[out] = a.neighbours[i];
            a.sharing[out] = uint8_t(std::min<uint32_t>(j - i, 255));
            ++out;
            i = j;
        }
        unique[v] = out - a.start[v];
    });
    // compact the ranges down
    uint32_t at = 0;
    for (size_t v = 0; v < nv; ++v) {
        const uint32_t from = a.start[v];
        for (uint32_t k = 0; k < unique[v]; ++k) {
            a.neighbours[at + k] = a.neighbours[from + k];
            a.sharing[at + k] = a.sharing[from + k];
        }
        a.start[v] = at;
        at += unique[v];
    }
    a.start[nv] = at;
    a.neighbours.resize(at);
    a.neighbours.shrink_to_fit();
    a.sharing.resize(at);
    a.sharing.shrink_to_fit();
    return a;
}

}  // namespace

void tangentFrame(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 a = std::abs(n.x) < 0.6f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(a - glm::dot(a, n) * n);
    v = glm::cross(n, u);
}

SurfaceGraph buildSurfaceGraph(const core::SurfaceMesh& mesh, float tolerance) {
    SurfaceGraph g;
    const core::Bounds box = mesh.bounds();
    g.diagonal = box.valid() ? glm::length(box.hi - box.lo) : 0.0f;
    const size_t n = mesh.vertexCount();

    // (1) weld: only vertices on a boundary edge of the mesh as given can lie on a seam (a
    // patch's or piece's own copy of a shared vertex); those in the same or a neighbouring
    // grid cell of size tolerance x diagonal and within that distance are one vertex
    // (union-find, so chains merge deterministically).
    std::vector<uint8_t> onOpenEdge(n, 0);
    {
        const Adjacency given = adjacencyOf(n, mesh.triangles);
        for (size_t v = 0; v < n; ++v)
            for (uint32_t k = given.start[v]; k < given.start[v + 1]; ++k)
                if (given.sharing[k] == 1) onOpenEdge[v] = 1;
    }
    const double cell = std::max(double(tolerance) * double(g.diagonal), 1e-30);
    std::unordered_map<CellKey, uint32_t, CellHash> firstInCell;
    std::vector<uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<uint32_t> candidates;
    for (size_t i = 0; i < n; ++i)
        if (onOpenEdge[i]) candidates.push_back(uint32_t(i));
    std::vector<CellKey> keys(candidates.size());
    for (size_t c = 0; c < candidates.size(); ++c) {
        const glm::vec3& p = mesh.positions[candidates[c]];
        keys[c] = {cellOf(p.x, cell), cellOf(p.y, cell), cellOf(p.z, cell)};
        firstInCell.emplace(keys[c], candidates[c]);
    }
    for (size_t c = 0; c < candidates.size(); ++c) {
        const uint32_t i = candidates[c];
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    auto it = firstInCell.find({keys[c].x + dx, keys[c].y + dy, keys[c].z + dz});
                    if (it == firstInCell.end() || it->second == i) continue;
                    if (glm::length(mesh.positions[it->second] - mesh.positions[i]) > float(cell)) continue;
                    const uint32_t a = findRoot(parent, i), b = findRoot(parent, it->second);
                    if (a != b) parent[std::max(a, b)] = std::min(a, b);
                }
    }
    g.weldOf.assign(n, 0);
    std::vector<uint32_t> welded(n, UINT32_MAX);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t r = findRoot(parent, uint32_t(i));
        if (welded[r] == UINT32_MAX) {
            welded[r] = uint32_t(g.positions.size());
            g.positions.push_back(mesh.positions[r]);
            g.normals.push_back(glm::vec3(0.0f));
        }
        g.weldOf[i] = welded[r];
        if (i < mesh.normals.size()) g.normals[welded[r]] += mesh.normals[i];
    }

    // (2) triangles over the welded vertices; the area-weighted normal where merged ones cancel.
    const size_t nv = g.positions.size();
    g.triangles.reserve(mesh.triangles.size());
    g.vertexArea.assign(nv, 0.0f);
    std::vector<glm::vec3> faceNormalSum(nv, glm::vec3(0.0f));
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::uvec3 w(g.weldOf[t.x], g.weldOf[t.y], g.weldOf[t.z]);
        if (w.x == w.y || w.y == w.z || w.x == w.z) continue;
        const glm::vec3 c = glm::cross(g.positions[w.y] - g.positions[w.x], g.positions[w.z] - g.positions[w.x]);
        const float area = 0.5f * glm::length(c);
        if (!(area > 0.0f)) continue;
        g.triangles.push_back(w);
        for (int k = 0; k < 3; ++k) {
            g.vertexArea[w[k]] += area / 3.0f;
            faceNormalSum[w[k]] += c;
        }
    }
    for (size_t v = 0; v < nv; ++v) {
        glm::vec3 nn = g.normals[v];
        if (!(glm::length(nn) > 1e-20f)) nn = faceNormalSum[v];
        const float len = glm::length(nn);
        g.normals[v] = len > 1e-30f ? nn / len : glm::vec3(0, 0, 1);
    }

    // (3) edges and neighbours (CSR): each undirected edge once, counted by its triangles;
    // the median edge length from every k-th edge (a deterministic sample of a million).
    Adjacency adj = adjacencyOf(nv, g.triangles);
    g.neighbourStart = std::move(adj.start);
    g.neighbours = std::move(adj.neighbours);
    g.boundaryNeighbour.assign(g.neighbours.size(), 0);
    g.onBoundary.assign(nv, 0);
    std::vector<uint32_t> part(nv);
    std::iota(part.begin(), part.end(), 0u);
    const size_t stride = std::max<size_t>(1, g.neighbours.size() / 2000000);
    std::vector<float> lengths;
    for (uint32_t a = 0; a < nv; ++a)
        for (uint32_t k = g.neighbourStart[a]; k < g.neighbourStart[a + 1]; ++k) {
            const uint32_t b = g.neighbours[k];
            const bool open = adj.sharing[k] == 1;
            g.boundaryNeighbour[k] = open;
            g.onBoundary[a] |= uint8_t(open);
            if (b < a) continue;  // each edge once, from its lower end
            ++g.edgeCount;
            if (open) ++g.boundaryEdges;
            if (adj.sharing[k] > 2) ++g.nonManifoldEdges;
            if (k % stride == 0) lengths.push_back(glm::length(g.positions[a] - g.positions[b]));
            const uint32_t ra = findRoot(part, a), rb = findRoot(part, b);
            if (ra != rb) part[std::max(ra, rb)] = std::min(ra, rb);
        }
    if (!lengths.empty()) {
        auto mid = lengths.begin() + long(lengths.size() / 2);
        std::nth_element(lengths.begin(), mid, lengths.end());
        g.medianEdge = *mid;
    }

    // (4) the connected parts
    std::vector<uint8_t> used(nv, 0);
    for (const glm::uvec3& t : g.triangles) used[t.x] = used[t.y] = used[t.z] = 1;
    for (size_t v = 0; v < nv; ++v) {
        g.usedVertices += used[v];
        if (used[v] && findRoot(part, uint32_t(v)) == v) ++g.parts;
    }
    return g;
}

std::vector<glm::vec3> weldValues(const SurfaceGraph& graph, const std::vector<glm::vec3>& values) {
    std::vector<glm::vec3> sum(graph.vertexCount(), glm::vec3(0.0f));
    std::vector<uint32_t> count(graph.vertexCount(), 0);
    for (size_t i = 0; i < values.size() && i < graph.weldOf.size(); ++i) {
        sum[graph.weldOf[i]] += values[i];
        ++count[graph.weldOf[i]];
    }
    for (size_t v = 0; v < sum.size(); ++v)
        if (count[v] > 1) sum[v] /= float(count[v]);
    return sum;
}

}  // namespace flowsurf::skeleton
