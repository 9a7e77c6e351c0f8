// flowsurf — what a reader's output must satisfy before any VTK filter touches it
// (private to src/io). VTK filters trust their input: an array shorter than the point
// count, a cell naming a point that does not exist, a polygon with two points or a
// hexahedron with five make vtkCellDataToPointData / vtkDataSetSurfaceFilter read out
// of bounds (seen as segfaults with fuzzed .vtk and .vtu files).
#pragma once

#include <string>

class vtkDataSet;

namespace flowsurf::io::detail {

// Throws FormatError naming `where` and the first offending array or cell.
void checkDataSet(vtkDataSet* data, const std::string& where);

}  // namespace flowsurf::io::detail
