// flowsurf — the critical points of a smoothed tangential field (doc/topology.md §2): each
// triangle whose three vectors wind around zero holds one, located where the linear
// interpolant vanishes, its index the winding number; zeros joined through a region slower
// than the cancellation speed merge into their net index (noise pairs cancel); the type
// comes from the Jacobian averaged over the analysis scale around the point.
// Cost: O(F) plus a neighbourhood average per point.
#pragma once

#include "skeleton/skeleton.h"
#include "skeleton/surface_graph.h"

#include <vector>

namespace flowsurf::skeleton {

struct FieldOnGraph {
    std::vector<glm::vec3> smoothed;   // welded, tangential, smoothed over the scale
    std::vector<glm::mat2> jacobians;  // of `smoothed`, in each vertex's tangentFrame
    float speed99 = 0.0f;
    float scale = 0.0f;
};

// The type of a critical point of index `index` whose Jacobian is `j` (eigenvalues out).
PointType classify(const glm::mat2& j, int index, float spiralRatio, glm::vec2 (&eigenvalues)[2]);

// Returns the points; `zeros` gets the count before merging.
std::vector<CriticalPoint> findCriticalPoints(const SurfaceGraph& graph, const FieldOnGraph& field,
                                              const SkeletonParams& params, size_t& zeros);

}  // namespace flowsurf::skeleton
