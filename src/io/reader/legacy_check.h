// flowsurf — a pre-check for legacy .vtk files (private to src/io). Files before
// version 5 store each cell list as "count id id ..." runs; VTK 9.1's reader walks the
// counts without bounds checks, so a truncated or corrupted POLYGONS/CELLS section
// segfaults (seen with fuzzed 4.2 files). The header line is also checked, since a
// garbled version number makes VTK read a 5.x file with the old layout.
#pragma once

#include <string>

namespace flowsurf::io::detail {

// Walks the geometry sections of POLYDATA and UNSTRUCTURED_GRID files (ASCII or
// BINARY) up to the first POINT_DATA/CELL_DATA and throws FormatError naming `path`
// if a cell list's counts do not add up to its declared size or the data ends early.
// Sections it does not know are left to VTK.
void checkLegacyFile(const std::string& path);

}  // namespace flowsurf::io::detail
