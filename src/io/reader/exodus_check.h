// flowsurf — checks an Exodus II file before vtkExodusIIReader sees it (private to
// src/io): the NetCDF layer reads a truncated classic file as zeros without complaint,
// which would render as a silently wrong surface. (What makes VTK's reader crash or loop
// is left to the reader process's limits.)
#pragma once

#include <string>

namespace flowsurf::io::detail {

// NetCDF classic / 64-bit offset / CDF5 files: parses the header and checks that every
// variable's data lies inside the file. HDF5-based (netCDF-4) files pass unchecked.
// Throws FormatError naming `path` (also for a file that is neither).
void checkExodusFile(const std::string& path);

}  // namespace flowsurf::io::detail
