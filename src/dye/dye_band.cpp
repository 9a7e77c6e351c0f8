#include "dye/dye_band.h"

#include "core/errors.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace flowsurf::methods {

namespace {
// Closest point to p on segment ab, as the parameter t in [0, 1].
float segmentParam(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    return len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
}
}  // namespace

glm::vec3 closestOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                            glm::vec3* bary) {
    // Inside: the projection onto the plane, when all its barycentric coordinates are >= 0.
    const glm::vec3 e0 = b - a, e1 = c - a, d = p - a;
    const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
    const float d20 = glm::dot(d, e0), d21 = glm::dot(d, e1);
    const float det = d00 * d11 - d01 * d01;
    if (det > 0.0f) {
        const float v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
        if (v >= 0.0f && w >= 0.0f && v + w <= 1.0f) {
            if (bary) *bary = glm::vec3(1.0f - v - w, v, w);
            return a + v * e0 + w * e1;
        }
    }
    // Outside (or degenerate): the nearest of the three edges.
    const float tab = segmentParam(p, a, b), tbc = segmentParam(p, b, c), tca = segmentParam(p, c, a);
    const glm::vec3 qab = a + tab * (b - a), qbc = b + tbc * (c - b), qca = c + tca * (a - c);
    const float dab = glm::dot(p - qab, p - qab), dbc = glm::dot(p - qbc, p - qbc), dca = glm::dot(p - qca, p - qca);
    if (dab <= dbc && dab <= dca) {
        if (bary) *bary = glm::vec3(1.0f - tab, tab, 0.0f);
        return qab;
    }
    if (dbc <= dca) {
        if (bary) *bary = glm::vec3(0.0f, 1.0f - tbc, tbc);
        return qbc;
    }
    if (bary) *bary = glm::vec3(tca, 0.0f, 1.0f - tca);
    return qca;
}

uint32_t triangleKey(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    // FNV-1a over the bits of the three positions in lexicographic order.
    const auto less = [](const glm::vec3& u, const glm::vec3& v) {
        return u.x != v.x ? u.x < v.x : u.y != v.y ? u.y < v.y : u.z < v.z;
    };
    glm::vec3 v[3] = {a, b, c};
    std::sort(v, v + 3, less);
    uint32_t h = 2166136261u;
    for (const glm::vec3& p : v)
        for (int i = 0; i < 3; ++i) {
            const uint32_t bits = std::bit_cast<uint32_t>(p[i]);
            for (int k = 0; k < 4; ++k) h = (h ^ ((bits >> (8 * k)) & 0xffu)) * 16777619u;
        }
    return h;
}

SurfacePoint closestOnSurface(const core::SurfaceMesh& mesh, const glm::vec3& p) {
    SurfacePoint best;
    best.position = p;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const glm::vec3 q = closestOnTriangle(p, a, b, c);
        const float d2 = glm::dot(q - p, q - p);
        const uint32_t key = triangleKey(a, b, c);
        if (!best.found || nearer(d2, key, best.distance2, best.key)) best = {q, d2, key, true};
    }
    return best;
}

DyeGrid makeDyeGrid(const core::Bounds& bounds, float h) {
    DyeGrid g;
    const glm::vec3 extent = glm::max(bounds.hi - bounds.lo, glm::vec3(0.0f));
    h = std::max(h, 1e-6f * std::max(glm::length(extent), 1e-30f));
    for (;;) {
        const float margin = (kDyeBandVoxels + 2.0f) * h;
        g.h = h;
        g.origin = bounds.lo - glm::vec3(margin);
        g.dims = glm::ivec3(glm::ceil((extent + 2.0f * margin) / h));
        if (g.voxelCount() <= kDyeMaxGridCells) return g;
        h *= 1.25f;
    }
}

DyeBand buildDyeBand(const core::SurfaceMesh& mesh, const DyeGrid& grid) {
    DyeBand band;
    band.grid = grid;
    band.index.assign(grid.voxelCount(), -1);
    const float radius = kDyeBandVoxels * grid.h;
    auto cell = [&](int x, int y, int z) { return (size_t(z) * size_t(grid.dims.y) + size_t(y)) * size_t(grid.dims.x) + size_t(x); };
    for (uint32_t ti = 0; ti < uint32_t(mesh.triangles.size()); ++ti) {
        const glm::uvec3 t = mesh.triangles[ti];
        const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const uint32_t key = triangleKey(a, b, c);
        const glm::vec3 lo = glm::min(a, glm::min(b, c)) - glm::vec3(radius), hi = glm::max(a, glm::max(b, c)) + glm::vec3(radius);
        // Voxels whose centres lie in [lo, hi].
        const glm::ivec3 i0 = glm::max(glm::ivec3(glm::ceil((lo - grid.origin) / grid.h - 0.5f)), glm::ivec3(0));
        const glm::ivec3 i1 = glm::min(glm::ivec3(glm::floor((hi - grid.origin) / grid.h - 0.5f)), grid.dims - 1);
        for (int z = i0.z; z <= i1.z; ++z)
            for (int y = i0.y; y <= i1.y; ++y)
                for (int x = i0.x; x <= i1.x; ++x) {
                    const glm::vec3 p = grid.origin + (glm::vec3(x, y, z) + 0.5f) * grid.h;
                    glm::vec3 bc;
                    const glm::vec3 q = closestOnTriangle(p, a, b, c, &bc);
                    const float d2 = glm::dot(q - p, q - p);
                    if (d2 > radius * radius) continue;
                    int32_t& idx = band.index[cell(x, y, z)];
                    if (idx < 0) {
                        idx = int32_t(band.closest.size());
                        band.closest.push_back(q);
                        band.triangle.push_back(ti);
                        band.barycentric.push_back(bc);
                        band.distance2.push_back(d2);
                        band.tieKey.push_back(key);
                    } else if (nearer(d2, key, band.distance2[size_t(idx)], band.tieKey[size_t(idx)])) {
                        band.closest[size_t(idx)] = q;
                        band.triangle[size_t(idx)] = ti;
                        band.barycentric[size_t(idx)] = bc;
                        band.distance2[size_t(idx)] = d2;
                        band.tieKey[size_t(idx)] = key;
                    }
                }
    }
    if (band.closest.size() > size_t(std::numeric_limits<int32_t>::max()))
        throw ConfigError("dye: the surface's narrow band is too large");

    orderByBrick(band);
    return band;
}

std::vector<uint32_t> orderByBrick(DyeBand& band) {
    // A counting sort on the brick of each voxel's cell.
    const DyeGrid& grid = band.grid;
    auto cell = [&](int x, int y, int z) { return (size_t(z) * size_t(grid.dims.y) + size_t(y)) * size_t(grid.dims.x) + size_t(x); };
    band.brickDims = (grid.dims + kDyeBrick - 1) / kDyeBrick;
    const size_t bricks = size_t(band.brickDims.x) * size_t(band.brickDims.y) * size_t(band.brickDims.z);
    band.brick.assign(band.closest.size(), 0);
    band.brickStart.assign(bricks + 1, 0);
    for (int z = 0; z < grid.dims.z; ++z)
        for (int y = 0; y < grid.dims.y; ++y)
            for (int x = 0; x < grid.dims.x; ++x) {
                const int32_t idx = band.index[cell(x, y, z)];
                if (idx < 0) continue;
                const glm::ivec3 b = glm::ivec3(x, y, z) / kDyeBrick;
                band.brick[size_t(idx)] =
                    uint32_t((size_t(b.z) * size_t(band.brickDims.y) + size_t(b.y)) * size_t(band.brickDims.x) + size_t(b.x));
                ++band.brickStart[band.brick[size_t(idx)] + 1];
            }
    for (size_t b = 0; b < bricks; ++b) band.brickStart[b + 1] += band.brickStart[b];
    std::vector<uint32_t> fill(band.brickStart.begin(), band.brickStart.end() - 1);
    std::vector<uint32_t> order(band.closest.size());  // new index of each old one
    for (size_t i = 0; i < order.size(); ++i) order[i] = fill[band.brick[i]]++;
    auto permute = [&](auto& v) {
        if (v.empty()) return;
        auto out = v;
        for (size_t i = 0; i < order.size(); ++i) out[order[i]] = v[i];
        v = std::move(out);
    };
    permute(band.closest);
    permute(band.triangle);
    permute(band.barycentric);
    permute(band.brick);
    permute(band.distance2);
    permute(band.tieKey);
    for (int32_t& idx : band.index)
        if (idx >= 0) idx = int32_t(order[size_t(idx)]);
    return order;
}

std::vector<glm::vec3> bandVelocity(const DyeBand& band, const core::SurfaceMesh& mesh, const std::string& field) {
    std::vector<glm::vec3> vel(band.size(), glm::vec3(0.0f));
    const core::VectorField* f = mesh.findField(field);
    if (!f) return vel;
    for (size_t i = 0; i < band.size(); ++i) {
        const glm::uvec3 t = mesh.triangles[band.triangle[i]];
        const glm::vec3 bc = band.barycentric[i];
        glm::vec3 v = bc.x * f->values[t.x] + bc.y * f->values[t.y] + bc.z * f->values[t.z];
        const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const glm::vec3 n = glm::cross(b - a, c - a);
        const float n2 = glm::dot(n, n);
        if (n2 > 0.0f) v -= n * (glm::dot(v, n) / n2);  // tangential: dye stays on the triangle's plane
        vel[i] = std::isfinite(v.x + v.y + v.z) ? v : glm::vec3(0.0f);
    }
    return vel;
}

}  // namespace flowsurf::methods
