// flowsurf — the surface the flow-topology analysis reads: one mesh, welded at coincident
// vertices (patches and pieces that were joined without merging their shared vertices
// become one surface, as the parallel seams are), with its edges, vertex neighbours, unit
// normals and the Euler characteristic V - E + F of what is welded (doc/topology.md).
// Input: core::SurfaceMesh positions, normals, triangles. Cost: O(V log V + F); memory ~30
// bytes per vertex and ~12 per triangle when nothing welds (the mesh's own positions, unit
// normals and triangles are read where they are), ~40 and ~24 more when something does.
#pragma once

#include "core/mesh.h"

#include <cstdint>
#include <span>
#include <vector>

namespace flowsurf::skeleton {

// Move-only: positions, normals and triangles are views, of the graph's own arrays or, where
// welding changed nothing, of the mesh's (which must then outlive the graph).
struct SurfaceGraph {
    std::vector<uint32_t> weldOf;        // input vertex -> welded vertex; empty: the same vertex
    std::span<const glm::vec3> positions;   // welded vertices
    std::span<const glm::vec3> normals;     // welded, unit (the mean of the merged normals)
    std::span<const glm::uvec3> triangles;  // over welded vertices; triangles left degenerate by welding dropped
    std::vector<uint32_t> neighbourStart, neighbours;  // CSR: neighbours[neighbourStart[v] .. [v+1]]
    std::vector<uint8_t> boundaryNeighbour;  // per CSR entry: the edge to that neighbour is a boundary edge
    std::vector<uint8_t> onBoundary;         // per vertex: on a boundary edge
    std::vector<float> vertexArea;       // a third of the adjacent triangles' areas
    size_t edgeCount = 0, boundaryEdges = 0, nonManifoldEdges = 0, parts = 0;
    float medianEdge = 0.0f;             // object units
    float diagonal = 0.0f;               // of the bounding box, object units

    size_t usedVertices = 0;             // welded vertices of at least one triangle

    SurfaceGraph() = default;
    SurfaceGraph(SurfaceGraph&&) = default;
    SurfaceGraph& operator=(SurfaceGraph&&) = default;
    SurfaceGraph(const SurfaceGraph&) = delete;
    SurfaceGraph& operator=(const SurfaceGraph&) = delete;

    size_t vertexCount() const { return positions.size(); }
    size_t inputVertexCount() const { return weldOf.empty() ? positions.size() : weldOf.size(); }
    uint32_t weldedVertex(size_t input) const { return weldOf.empty() ? uint32_t(input) : weldOf[input]; }
    long eulerCharacteristic() const {
        return long(usedVertices) - long(edgeCount) + long(triangles.size());
    }
    bool closed() const { return boundaryEdges == 0; }

    // what the views show where they are not the mesh's
    std::vector<glm::vec3> ownPositions, ownNormals;
    std::vector<glm::uvec3> ownTriangles;
};

// Welds vertices closer than `tolerance` x the bounding-box diagonal (the positions are
// binned on a grid of that size and merged with their grid neighbours). `mesh` is valid
// (core::validateMesh).
SurfaceGraph buildSurfaceGraph(const core::SurfaceMesh& mesh, float tolerance = 1e-6f);

// The values of a per-input-vertex array on the welded vertices (the mean of the merged).
std::vector<glm::vec3> weldValues(const SurfaceGraph& graph, const std::vector<glm::vec3>& values);

// A right-handed orthonormal frame (u, v) of the tangent plane of unit normal n, the same
// for the same n everywhere.
void tangentFrame(const glm::vec3& n, glm::vec3& u, glm::vec3& v);

}  // namespace flowsurf::skeleton
