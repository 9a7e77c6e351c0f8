// flowsurf — ParaView's surface (vtkPolyData, or a composite of them) as a
// core::SurfaceMesh: points, point normals (computed where absent), polygons and strips
// as triangles, and one 3-component point array; its camera as a core::Camera. No
// libvtk9/src/io: ParaView's own VTK.
#ifndef polydata_to_mesh_h
#define polydata_to_mesh_h

#include "core/camera.h"
#include "core/mesh.h"
#include "core/time_series.h"

#include <string>

class vtkCamera;
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

// ParaView's piece of the surface as the one step session::Playback reads.
class PieceSteps final : public core::StepProvider
{
public:
  core::SurfaceMesh mesh;
  size_t count() const override { return 1; }
  double time(size_t) const override { return 0.0; }
  core::SurfaceMesh load(size_t) override { return mesh; }
  std::string label(size_t) const override { return "FlowSurf input"; }
  core::Bounds bounds() override { return mesh.bounds(); }
};

core::Camera cameraOf(vtkCamera* camera);

}  // namespace flowsurf::paraview

#endif
