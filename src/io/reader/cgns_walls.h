// flowsurf — a CGNS boundary patch as a surface of its zone's volume (private to src/io):
// the patch's faces over the points they use, with the volume's point arrays at those
// points and, for cell-centred solutions, each face given the values of the volume cell
// it bounds. That cell (wallCells) is also where a quantity measured next to the wall
// starts from, such as the wall shear stress from the first cell's velocity.
#pragma once

#include "io/reader/cgns_boundaries.h"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkDataSet;
class vtkPolyData;

namespace flowsurf::io::detail {

// For each face of `patch`, the id of the cell of `volume` that has it as a face (-1 where
// none has: a face on no cell of this zone).
std::vector<vtkIdType> wallCells(vtkDataSet* volume, const CgnsPatch& patch);

// The patch as polygons over its own points. `cells`: wallCells(volume, patch), or empty
// when the volume has no cell arrays. Throws FormatError ("WHERE: ...") when a face names
// a point the volume does not have.
vtkSmartPointer<vtkPolyData> patchSurface(vtkDataSet* volume, const CgnsPatch& patch, const std::vector<vtkIdType>& cells,
                                          const std::string& where);

}  // namespace flowsurf::io::detail
