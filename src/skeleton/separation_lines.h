// flowsurf — separation and attachment lines (doc/topology.md §3), by the parallel-vectors
// form of Kenwright, Henze and Levit's eigenvector method: where the smoothed field v is an
// eigenvector of its Jacobian J (v x Jv = 0, a zero set found per triangle), with lambda_a
// the rate along v and lambda_b the other eigenvalue, the rate across, a line is
// separation where lambda_b < min(0, lambda_a) (the flow converges across faster than
// along) and attachment where lambda_b > max(0, lambda_a); pieces that run along the flow
// are joined across triangles into polylines and filtered by length and strength. Open
// separation (no critical point on the line) and a saddle's separatrices near it are both
// such lines. Cost: O(F).
#pragma once

#include "skeleton/critical_points.h"

namespace flowsurf::skeleton {

std::vector<SkeletonLine> findSeparationLines(const SurfaceGraph& graph, const FieldOnGraph& field,
                                              const SkeletonParams& params);

}  // namespace flowsurf::skeleton
