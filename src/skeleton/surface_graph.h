// flowsurf — the surface the flow-topology analysis reads: one mesh, welded at coincident
// vertices (patches and pieces that were joined without merging their shared vertices
// become one surface, as the parallel seams are), with its edges, vertex neighbours, unit
// normals and the Euler characteristic V - E + F of what is welded (doc/topology.md).
// Input: core::SurfaceMesh positions, normals, triangles. Cost: O(V log V + F), ~40 bytes
// per vertex and ~24 per triangle.
#pragma once

#include "core/mesh.h"

#include <cstdint>
#include <vector>

namespace flowsurf::skeleton {

struct SurfaceGraph {
    std::vector<uint32_t> weldOf;        // input vertex -> welded vertex
    std::vector<glm::vec3> positions;    // welded vertices
    std::vector<glm::vec3> normals;      // welded, unit (the mean of the merged normals)
    std::vector<glm::uvec3> triangles;   // over welded vertices; triangles left degenerate by welding dropped
    std::vector<uint32_t> neighbourStart, neighbours;  // CSR: neighbours[neighbourStart[v] .. [v+1]]
    std::vector<uint8_t> boundaryNeighbour;  // per CSR entry: the edge to that neighbour is a boundary edge
    std::vector<uint8_t> onBoundary;         // per vertex: on a boundary edge
    std::vector<float> vertexArea;       // a third of the adjacent triangles' areas
    size_t edgeCount = 0, boundaryEdges = 0, nonManifoldEdges = 0, parts = 0;
    float medianEdge = 0.0f;             // object units
    float diagonal = 0.0f;               // of the bounding box, object units

    size_t usedVertices = 0;             // welded vertices of at least one triangle

    size_t vertexCount() const { return positions.size(); }
    long eulerCharacteristic() const {
        return long(usedVertices) - long(edgeCount) + long(triangles.size());
    }
    bool closed() const { return boundaryEdges == 0; }
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
