// flowsurf — dye, the narrow band (CPU, no GL): the voxels of a regular grid that lie
// within a few voxels of the surface, each with its closest surface point cp(x) and the
// tangential velocity there. The closest point method [Ruuth & Merriman 2008, J. Comput.
// Phys. 227] keeps dye on the surface by extending it along normals: u(x) = u(cp(x)).
// Inputs: mesh + vector field. Output: dense index grid (-1: not in the band) + band lists.
// Cost: one closest-point test per triangle and voxel of its box grown by the band radius.
#pragma once

#include "core/mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace flowsurf::methods {

struct DyeGrid {
    glm::vec3 origin{0.0f};  // corner of voxel (0,0,0); voxel centres at origin + (i + 0.5) h
    float h = 1.0f;          // voxel size, object units
    glm::ivec3 dims{0};
    size_t voxelCount() const { return size_t(dims.x) * size_t(dims.y) * size_t(dims.z); }
};

// Grid cells a surface may use at most (the dense index grid is 4 bytes a cell).
inline constexpr size_t kDyeMaxGridCells = size_t(32) << 20;
// Band radius in voxels: every corner of the trilinear stencil of a point on the surface
// lies within sqrt(3) h of it.
inline constexpr float kDyeBandVoxels = 2.0f;

// A grid over `bounds` (grown by the band) with voxel size `h`, coarsened until it has at
// most kDyeMaxGridCells cells.
DyeGrid makeDyeGrid(const core::Bounds& bounds, float h);

// Side of a brick in grid cells: the band's voxels are stored brick by brick, so the
// voxels of the bricks that hold dye (and those it can reach next) are index ranges.
inline constexpr int kDyeBrick = 8;

struct DyeBand {
    DyeGrid grid;
    glm::ivec3 brickDims{0};            // bricks per axis
    std::vector<uint32_t> brickStart;   // per brick (x fastest) + 1: first band voxel; voxels of b: [start[b], start[b+1])
    std::vector<int32_t> index;         // per grid cell: band voxel or -1
    std::vector<glm::vec3> closest;     // per band voxel: cp(x), object space
    std::vector<uint32_t> triangle;     // per band voxel: triangle holding cp(x)
    std::vector<glm::vec3> barycentric; // per band voxel: cp(x) in that triangle
    std::vector<uint32_t> brick;        // per band voxel: its brick
    std::vector<float> distance2;       // per band voxel: squared distance to cp(x)
    std::vector<uint32_t> tieKey;       // per band voxel: triangleKey of the triangle holding cp(x)
    size_t size() const { return closest.size(); }
};

// A key of a triangle made of its vertex positions only (not of its place in a mesh): of two
// candidates at the same distance the smaller key wins, so a mesh and its pieces, whatever
// their triangle order, pick the same closest point (dye/dye_shared.h).
uint32_t triangleKey(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
// Candidate (d2, key) nearer than (bestD2, bestKey): by distance, on a tie by key.
inline bool nearer(float d2, uint32_t key, float bestD2, uint32_t bestKey) {
    return d2 < bestD2 || (d2 == bestD2 && key < bestKey);
}

// Band voxels within kDyeBandVoxels * h of the surface, ordered by brick.
DyeBand buildDyeBand(const core::SurfaceMesh& mesh, const DyeGrid& grid);
// Sets brickDims, brick and brickStart from `index` and orders the per-voxel arrays (those
// not empty) brick by brick, keeping the order within a brick; `index` follows. Returns
// the new place of each voxel (for arrays the caller keeps beside the band).
std::vector<uint32_t> orderByBrick(DyeBand& band);

// Tangential velocity at each band voxel's closest point: barycentric blend of the vertex
// vectors of `field`, projected onto the triangle's plane (object units per data time).
std::vector<glm::vec3> bandVelocity(const DyeBand& band, const core::SurfaceMesh& mesh, const std::string& field);

// Closest point on triangle (a, b, c) to p, with its barycentric coordinates.
glm::vec3 closestOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                            glm::vec3* bary = nullptr);
// Closest point of the whole surface to p (every triangle: for the few dye sources), with
// its squared distance and triangle key (ties broken as in the band). No triangles: `found`
// false.
struct SurfacePoint {
    glm::vec3 position{0.0f};
    float distance2 = 0.0f;
    uint32_t key = 0;
    bool found = false;
};
SurfacePoint closestOnSurface(const core::SurfaceMesh& mesh, const glm::vec3& p);

}  // namespace flowsurf::methods
