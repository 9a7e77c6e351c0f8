// flowsurf — checks an Exodus II file before vtkExodusIIReader sees it (private to
// src/io). The Exodus library prints its complaints straight to stderr, the NetCDF
// layer reads a truncated classic file as zeros without complaint, and VTK 9.1 reads
// out of bounds (segfault) when element connectivity names a node that does not exist.
#pragma once

#include <string>

namespace flowsurf::io::detail {

// NetCDF classic / 64-bit offset / CDF5 files: parses the header, checks that every
// variable's data lies inside the file and that every "connect*" entry is a node
// number in 1..num_nodes. HDF5-based (netCDF-4) files pass unchecked. Throws
// FormatError naming `path`.
void checkExodusFile(const std::string& path);

}  // namespace flowsurf::io::detail
