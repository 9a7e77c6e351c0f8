// flowsurf — a pre-check for legacy .vtk files (private to src/io). Files before
// version 5 store each cell list as "count id id ..." runs; VTK 9.1's reader walks the
// counts without bounds checks, past the end of its buffer, and takes what lies there as
// point indices: a crash, or (where that memory holds small numbers, as under
// AddressSanitizer) a surface drawn from garbage without complaint. The crash the reader
// process contains; the silently wrong surface only this check catches. The header line is
// also checked, since a garbled version number makes VTK read a 5.x file with the old
// layout.
#pragma once

#include <string>

namespace flowsurf::io::detail {

// Walks the geometry sections of POLYDATA and UNSTRUCTURED_GRID files (ASCII or
// BINARY) up to the first POINT_DATA/CELL_DATA and throws FormatError naming `path`
// if a cell list's counts do not add up to its declared size or the data ends early.
// Sections it does not know are left to VTK.
void checkLegacyFile(const std::string& path);

}  // namespace flowsurf::io::detail
