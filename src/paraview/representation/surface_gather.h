// flowsurf — the pieces of a surface that ParaView's processes hold, gathered onto process 0
// for an analysis that needs the whole surface (the flow topology: a neighbourhood fit near a
// piece boundary reads the neighbours' triangles, lines run across pieces), and the rule that
// one process's error is every process's. Collectives over ParaView's
// vtkMultiProcessController; with no controller or one process they return at once. Used
// by the FlowSurf Topology filter and the representation's FlowSurfTopology overlay.
#pragma once

#include "core/mesh.h"
#include "skeleton/skeleton.h"

#include <string>

class vtkMultiProcessController;

namespace flowsurf::paraview {

// Collective: "" when no process has an error; else the first failing process's message,
// followed by "(on process K of N)" under MPI, the same on every process.
std::string agreedError(vtkMultiProcessController* controller, const std::string& mine);

// Collective: on process 0 every process's positions, triangles and first vector field,
// concatenated in process order (vertices on the seams appear once per piece, as the
// analysis welds them); on the others an empty mesh. Normals are not carried.
core::SurfaceMesh gatherToRoot(vtkMultiProcessController* controller, const core::SurfaceMesh& piece);

// Collective: process 0's `result` on every process (the others' argument is ignored), every
// member carried exactly (floats and counts as doubles: one length, then the values).
skeleton::Skeleton broadcastFromRoot(vtkMultiProcessController* controller, const skeleton::Skeleton& result);

}  // namespace flowsurf::paraview
