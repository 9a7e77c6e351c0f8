// flowsurf — a pre-check for VTK XML files with compressed arrays (private to src/io).
// vtkXMLDataParser sizes a table by the block count in each compressed array's header
// before reading anything else: a corrupted count (say 2^31) costs gigabytes of memory
// and minutes, so such headers are refused first.
#pragma once

#include <string>

namespace flowsurf::io::detail {

// Throws FormatError if a compressed array (appended raw/base64 or inline binary)
// declares more blocks than the file has bytes for, or its header is cut off. Files
// the XML parser refuses are left to the reader, which reports them.
void checkXmlCompressionHeaders(const std::string& path);

}  // namespace flowsurf::io::detail
