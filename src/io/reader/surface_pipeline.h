// flowsurf — from a reader's output to a triangle surface with point vector fields
// (private to src/io). Stages, in order:
//   check data sets → surface per block → merge blocks (arrays on some blocks padded) → cell data to point data →
//   triangulate → copy into core::SurfaceMesh → core::validateMesh.
#pragma once

#include "core/mesh.h"
#include "io/reader/vtk_messages.h"

#include <functional>
#include <map>
#include <string>

class vtkDataObject;
class vtkDataSet;

namespace flowsurf::io::detail {

// Calls `visit` for every non-empty data set, `data` itself or the leaves of a composite,
// with its block's name (an OpenFOAM patch name; "block N" when unnamed; empty for `data`).
void forEachNamedLeaf(vtkDataObject* data, const std::function<void(vtkDataSet*, const std::string&)>& visit);

// The units of the arrays of `data`'s leaves (their UNITS_LABEL, set by the OpenFOAM
// source from the fields' dimensions), by array name.
std::map<std::string, std::string> arrayUnits(vtkDataObject* data);

// All stages, validation included; the mesh's fields carry arrayUnits(data).
core::SurfaceMesh readSurfaceMesh(vtkDataObject* data, VtkMessageTrap& trap, const std::string& where);

}  // namespace flowsurf::io::detail
