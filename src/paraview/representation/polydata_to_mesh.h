// flowsurf — ParaView's surface (vtkPolyData, or a composite of them) as a
// core::SurfaceMesh: points, point normals (computed where absent), polygons and strips
// as triangles, and one 3-component point array. No libvtk9/src/io: ParaView's own VTK.
#ifndef polydata_to_mesh_h
#define polydata_to_mesh_h

#include "core/mesh.h"

#include <string>

class vtkDataObject;

namespace flowsurf::paraview {

// Appends every vtkPolyData leaf of `data`. Throws FieldError naming `vectors` when a
// non-empty leaf lacks that 3-component point array.
core::SurfaceMesh toSurfaceMesh(vtkDataObject* data, const std::string& vectors);

}  // namespace flowsurf::paraview

#endif
