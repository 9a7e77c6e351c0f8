// flowsurf — a flow-topology result (skeleton::Skeleton) as vtkPolyData, the one layout of
// `flowsurf topology -o OUT.vtp` (skeleton_vtp.cpp, against Debian's VTK) and the ParaView
// filter FlowSurf Topology (compiled there against ParaView's VTK): the critical points as vertices with point arrays
// `type` (int, PointType), `type_name`, `index` (Poincaré), the separation and attachment
// lines as polylines with cell arrays `kind` (int, LineKind; -1 on the vertices),
// `kind_name` and the point array `strength` (0 on the critical points); field data
// `euler_characteristic`, `index_sum`, `closed` and `parts` (one int each).
#pragma once

#include "skeleton/skeleton.h"

#include "vtkSmartPointer.h"

class vtkPolyData;

namespace flowsurf::io {

vtkSmartPointer<vtkPolyData> skeletonPolyData(const skeleton::Skeleton& s);

}  // namespace flowsurf::io
