// flowsurf — ParaView's surface (vtkPolyData, or a composite of them) as a
// core::SurfaceMesh: points, point normals (computed where absent), polygons and strips
// as triangles, and one 3-component point array. No libvtk9/src/io: ParaView's own VTK.
#ifndef polydata_to_mesh_h
#define polydata_to_mesh_h

#include "core/mesh.h"

#include <string>

class vtkDataObject;

namespace flowsurf::paraview {

// A point array ParaView colours the surface by, as the value its lookup table maps:
// one component, or the magnitude over all of them (component -1).
struct ColorSource
{
  std::string array;
  int component = -1;
};
// The scalar a ColorSource adds to the mesh (NaN where a leaf lacks the array).
inline const char* const kColorScalarName = "ParaView colour";

// Appends every vtkPolyData leaf of `data`. Throws FieldError naming `vectors` when a
// non-empty leaf lacks that 3-component point array. With `color`, the mesh also carries
// its values as the scalar kColorScalarName.
core::SurfaceMesh toSurfaceMesh(vtkDataObject* data, const std::string& vectors,
  const ColorSource* color = nullptr);

}  // namespace flowsurf::paraview

#endif
