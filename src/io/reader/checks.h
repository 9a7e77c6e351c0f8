// flowsurf — checks of what VTK would read silently wrong, made in the reader process
// before VTK or any filter sees the data (private to src/io). What makes a reader crash or
// loop is left to the process's limits and sandbox (io/reader_process.h). Each throws
// FormatError naming the file (`where` for a data set) and what is wrong; IoError if the
// file cannot be opened.
#pragma once

#include <string>

class vtkDataSet;

namespace flowsurf::io::detail {

// Legacy .vtk files before version 5 store each cell list as "count id id ..." runs; VTK
// 9.1's reader walks the counts without bounds checks, past the end of its buffer, and takes
// what lies there as point indices: a crash, or (where that memory holds small numbers, as
// under AddressSanitizer) a surface drawn from garbage without complaint. Walks the geometry
// sections of POLYDATA and UNSTRUCTURED_GRID files (ASCII or BINARY) up to the first
// POINT_DATA/CELL_DATA: a cell list's counts must add up to its declared size and the data
// must not end early; sections it does not know are left to VTK. The header line is also
// checked, since a garbled version number makes VTK read a 5.x file with the old layout.
void checkLegacyFile(const std::string& path);

// The NetCDF layer reads a truncated classic Exodus II file as zeros. For NetCDF classic,
// 64-bit offset and CDF5 files: parses the header and checks that every variable's data
// lies inside the file. HDF5-based (netCDF-4) files pass unchecked; a file that is neither
// is refused.
void checkExodusFile(const std::string& path);

// VTK filters trust their input: an array shorter than the point count, a cell naming a
// point that does not exist, a polygon with two points or a hexahedron with five make
// vtkCellDataToPointData / vtkDataSetSurfaceFilter read out of bounds (seen as segfaults
// with fuzzed .vtk and .vtu files). Names the first offending array or cell.
void checkDataSet(vtkDataSet* data, const std::string& where);

}  // namespace flowsurf::io::detail
