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
// boundary edge, above 2: non-manifold). Built from the triangles' directed sides listed at
// their first vertex (3 F entries): a consistently oriented manifold lists every interior
// edge once from each end, so only the sides with no side back (the boundary, flipped
// triangles) add the reverse entry. Peak memory ~ 2 x 3 F entries.
struct Adjacency {
    std::vector<uint32_t> start, neighbours;
    std::vector<uint8_t> sharing;  // per entry, capped at 255
};

struct DirectedSides {
    std::vector<uint32_t> start, to;  // sorted per vertex
    // how many sides a -> b
    uint32_t count(uint32_t a, uint32_t b) const {
        const auto r = std::equal_range(to.begin() + start[a], to.begin() + start[a + 1], b);
        return uint32_t(r.second - r.first);
    }
};

DirectedSides directedSides(size_t nv, const std::span<const glm::uvec3>& triangles) {
    DirectedSides d;
    d.start.assign(nv + 1, 0);
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) ++d.start[t[k] + 1];
    for (size_t v = 0; v < nv; ++v) d.start[v + 1] += d.start[v];
    d.to.resize(d.start[nv]);
    std::vector<uint32_t> fill(d.start.begin(), d.start.end() - 1);
    for (const glm::uvec3& t : triangles)
        for (int k = 0; k < 3; ++k) d.to[fill[t[k]]++] = t[(k + 1) % 3];
    detail::parallelFor(nv, [&](size_t v) { std::sort(d.to.begin() + d.start[v], d.to.begin() + d.start[v + 1]); });
    return d;
}

// Visits each vertex's distinct side ends b (a -> b) with the count each way.
template <typename Fn>
void forEachSide(const DirectedSides& d, uint32_t a, Fn&& fn) {
    for (uint32_t i = d.start[a]; i < d.start[a + 1];) {
        uint32_t j = i;
        while (j < d.start[a + 1] && d.to[j] == d.to[i]) ++j;
        fn(d.to[i], j - i, d.count(d.to[i], a));
        i = j;
    }
}

Adjacency adjacencyOf(size_t nv, const std::span<const glm::uvec3>& triangles) {
    const DirectedSides d = directedSides(nv, triangles);
    // (a) the entries per vertex: its distinct side ends, and the starts of sides with none back
    Adjacency a;
    a.start.assign(nv + 1, 0);
    for (uint32_t v = 0; v < nv; ++v)
        forEachSide(d, v, [&](uint32_t b, uint32_t, uint32_t back) {
            ++a.start[v + 1];
            if (back == 0) ++a.start[b + 1];
        });
    for (size_t v = 0; v < nv; ++v) a.start[v + 1] += a.start[v];
    // (b) filled, then sorted per vertex with the counts beside
    a.neighbours.resize(a.start[nv]);
    a.sharing.resize(a.start[nv]);
    std::vector<uint32_t> fill(a.start.begin(), a.start.end() - 1);
    for (uint32_t v = 0; v < nv; ++v)
        forEachSide(d, v, [&](uint32_t b, uint32_t forth, uint32_t back) {
            const auto shared = uint8_t(std::min<uint32_t>(forth + back, 255));
            a.neighbours[fill[v]] = b;
            a.sharing[fill[v]++] = shared;
            if (back != 0) return;
            a.neighbours[fill[b]] = v;
            a.sharing[fill[b]++] = shared;
        });
    detail::parallelFor(nv, [&](size_t v) {
        const uint32_t b = a.start[v], e = a.start[v + 1];
        std::vector<uint64_t> keyed(e - b);  // neighbour, then its count in the low byte
        for (uint32_t i = b; i < e; ++i) keyed[i - b] = uint64_t(a.neighbours[i]) << 8 | a.sharing[i];
        std::sort(keyed.begin(), keyed.end());
        for (uint32_t i = b; i < e; ++i) {
            a.neighbours[i] = uint32_t(keyed[i - b] >> 8);
            a.sharing[i] = uint8_t(keyed[i - b] & 0xff);
        }
    });
    return a;
}

}  // namespace

void tangentFrame(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 a = std::abs(n.x) < 0.6f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    u = glm::normalize(a - glm::dot(a, n) * n);
    v = glm::cross(n, u);
}

namespace {

// (1) weld: only vertices on a boundary edge of the mesh as given can lie on a seam (a
// patch's or piece's own copy of a shared vertex); those in the same or a neighbouring grid
// cell of size `cell` and within that distance are one vertex (union-find, so chains merge
// deterministically). The root of each input vertex; true when any merged.
bool weldRoots(const core::SurfaceMesh& mesh, const Adjacency& given, double cell, std::vector<uint32_t>& parent) {
    const size_t n = mesh.vertexCount();
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<uint32_t> candidates;
    for (uint32_t v = 0; v < n; ++v)
        for (uint32_t k = given.start[v]; k < given.start[v + 1]; ++k)
            if (given.sharing[k] == 1) {
                candidates.push_back(v);
                break;
            }
    std::unordered_map<CellKey, uint32_t, CellHash> firstInCell;
    std::vector<CellKey> keys(candidates.size());
    for (size_t c = 0; c < candidates.size(); ++c) {
        const glm::vec3& p = mesh.positions[candidates[c]];
        keys[c] = {cellOf(p.x, cell), cellOf(p.y, cell), cellOf(p.z, cell)};
        firstInCell.emplace(keys[c], candidates[c]);
    }
    bool merged = false;
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
                    merged |= a != b;
                }
    }
    return merged;
}

// The welded vertices (positions, the sums of their normals) and weldOf.
void weldVertices(const core::SurfaceMesh& mesh, std::vector<uint32_t>& parent, SurfaceGraph& g) {
    const size_t n = mesh.vertexCount();
    g.weldOf.assign(n, 0);
    std::vector<uint32_t> welded(n, UINT32_MAX);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t r = findRoot(parent, uint32_t(i));
        if (welded[r] == UINT32_MAX) {
            welded[r] = uint32_t(g.ownPositions.size());
            g.ownPositions.push_back(mesh.positions[r]);
            g.ownNormals.push_back(glm::vec3(0.0f));
        }
        g.weldOf[i] = welded[r];
        if (i < mesh.normals.size()) g.ownNormals[welded[r]] += mesh.normals[i];
    }
    g.positions = g.ownPositions;
}

// (2) triangles over the welded vertices, their areas per vertex; the normals unit, the
// area-weighted one where merged ones cancel. The mesh's own arrays where they serve.
void weldTriangles(const core::SurfaceMesh& mesh, bool welded, SurfaceGraph& g) {
    const size_t nv = g.positions.size();
    g.vertexArea.assign(nv, 0.0f);
    std::vector<glm::vec3> faceNormalSum;
    auto normalSum = [&](uint32_t v) -> glm::vec3& {
        if (faceNormalSum.empty()) faceNormalSum.assign(nv, glm::vec3(0.0f));
        return faceNormalSum[v];
    };
    auto vertexOf = [&](uint32_t i) { return welded ? g.weldOf[i] : i; };
    size_t kept = 0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::uvec3 w(vertexOf(t.x), vertexOf(t.y), vertexOf(t.z));
        if (w.x == w.y || w.y == w.z || w.x == w.z) continue;
        const glm::vec3 c = glm::cross(g.positions[w.y] - g.positions[w.x], g.positions[w.z] - g.positions[w.x]);
        const float area = 0.5f * glm::length(c);
        if (!(area > 0.0f)) continue;
        // a copy once one is dropped or changed: the ones kept so far are the mesh's first
        if (welded || kept != size_t(&t - mesh.triangles.data())) {
            if (g.ownTriangles.size() != kept) g.ownTriangles.assign(mesh.triangles.begin(), mesh.triangles.begin() + long(kept));
            g.ownTriangles.push_back(w);
        }
        ++kept;
        for (int k = 0; k < 3; ++k) {
            g.vertexArea[w[k]] += area / 3.0f;
            if (welded) normalSum(w[k]) += c;
        }
    }
    if (!welded && kept != mesh.triangles.size() && g.ownTriangles.size() != kept)  // only the last ones dropped
        g.ownTriangles.assign(mesh.triangles.begin(), mesh.triangles.begin() + long(kept));
    g.triangles = kept == mesh.triangles.size() && !welded ? std::span<const glm::uvec3>(mesh.triangles)
                                                          : std::span<const glm::uvec3>(g.ownTriangles);
    if (!welded) {
        const bool unit = mesh.normals.size() == nv && std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const glm::vec3& n) {
                              return std::abs(glm::dot(n, n) - 1.0f) < 1e-5f;
                          });
        if (unit) {
            g.normals = mesh.normals;
            return;
        }
        g.ownNormals.assign(nv, glm::vec3(0.0f));
        std::copy_n(mesh.normals.begin(), std::min(nv, mesh.normals.size()), g.ownNormals.begin());
        for (const glm::uvec3& t : g.triangles) {
            const glm::vec3 c = glm::cross(g.positions[t.y] - g.positions[t.x], g.positions[t.z] - g.positions[t.x]);
            for (int k = 0; k < 3; ++k) normalSum(t[k]) += c;
        }
    }
    for (size_t v = 0; v < nv; ++v) {
        glm::vec3 nn = g.ownNormals[v];
        if (!(glm::length(nn) > 1e-20f) && !faceNormalSum.empty()) nn = faceNormalSum[v];
        const float len = glm::length(nn);
        g.ownNormals[v] = len > 1e-30f ? nn / len : glm::vec3(0, 0, 1);
    }
    g.normals = g.ownNormals;
}

// (3) edges and neighbours (CSR): each undirected edge once, counted by its triangles; the
// median edge length from every k-th edge (a deterministic sample of a million); (4) the
// connected parts.
void countEdges(Adjacency adj, SurfaceGraph& g) {
    const size_t nv = g.positions.size();
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
    std::vector<uint8_t> used(nv, 0);
    for (const glm::uvec3& t : g.triangles) used[t.x] = used[t.y] = used[t.z] = 1;
    for (size_t v = 0; v < nv; ++v) {
        g.usedVertices += used[v];
        if (used[v] && findRoot(part, uint32_t(v)) == v) ++g.parts;
    }
}

}  // namespace

SurfaceGraph buildSurfaceGraph(const core::SurfaceMesh& mesh, float tolerance) {
    SurfaceGraph g;
    const core::Bounds box = mesh.bounds();
    g.diagonal = box.valid() ? glm::length(box.hi - box.lo) : 0.0f;
    Adjacency given = adjacencyOf(mesh.vertexCount(), mesh.triangles);
    std::vector<uint32_t> parent;
    const bool welded = weldRoots(mesh, given, std::max(double(tolerance) * double(g.diagonal), 1e-30), parent);
    if (welded) {
        weldVertices(mesh, parent, g);
    } else {
        g.positions = mesh.positions;
    }
    parent = {};
    weldTriangles(mesh, welded, g);
    // the mesh's own neighbours serve when welding changed no vertex and dropped no triangle
    if (welded || g.triangles.size() != mesh.triangles.size()) given = adjacencyOf(g.positions.size(), g.triangles);
    countEdges(std::move(given), g);
    return g;
}

std::vector<glm::vec3> weldValues(const SurfaceGraph& graph, const std::vector<glm::vec3>& values) {
    if (graph.weldOf.empty()) return values;
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
