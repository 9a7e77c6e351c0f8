// flowsurf — the seams of a surface split over processes [docs/parallel.md]. A piece's edge
// with one triangle is either a boundary of the surface or a seam of the partition (the
// neighbouring triangle lies in another process's piece). The IBFVS edge mask [L §IV-E.2]
// outlines boundaries and silhouettes: a seam is neither, but a silhouette may run along
// one. The processes exchange their one-triangle edges (positions: the pieces share the
// seam's vertices): where two lie at the same position — two pieces', or one piece's own
// duplicated vertices (a source that made its pieces with seams, then redistributed) — it
// is a seam, drawn by the first side (lowest rank) as an ordinary edge with the other
// side's opposite vertex.
// Cost: collective, once per uploaded geometry; 36 bytes per one-triangle edge of a piece
// (O(sqrt n) for a piece of n triangles) to every process.
#pragma once

#include "core/mesh.h"
#include "parallel/process_group.h"

#include <cstdint>
#include <vector>

namespace flowsurf::methods {

// One edge as the edge mask draws it (GL_LINES_ADJACENCY): v0 -> v1 in the winding of the
// triangle (v0, v1, a), the other triangle (v1, v0, b).
struct AdjacentEdge {
    glm::vec3 v0, v1, a, b;
};

struct PieceSeams {
    std::vector<uint64_t> edges;      // this piece's seam edges: (min vertex << 32) | max vertex
    std::vector<AdjacentEdge> drawn;  // the seams this process draws, both sides known
};

// Collective over `group`; nullptr: one process, whose surface may still be made of pieces
// (ParaView's client rendering the pieces it was delivered, appended patches).
PieceSeams pieceSeams(ProcessGroup* group, const core::SurfaceMesh& piece);

}  // namespace flowsurf::methods
