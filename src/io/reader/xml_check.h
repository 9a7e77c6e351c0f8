// flowsurf — a pre-check for VTK XML files with compressed arrays (private to src/io).
// vtkXMLDataParser trusts each compressed array's block table: a corrupted block count
// (say 2^31) costs gigabytes of memory and minutes, a table shorter than the array
// makes it read past its buffers (segfault). Such headers are refused first.
#pragma once

#include <string>

namespace flowsurf::io::detail {

// Throws FormatError if a compressed array's header (appended raw/base64 or inline
// binary) is cut off, declares more blocks or compressed bytes than the file holds,
// or covers fewer bytes than the piece's point/cell counts need. Files the XML
// parser refuses are left to the reader, which reports them.
void checkXmlCompressionHeaders(const std::string& path);

}  // namespace flowsurf::io::detail
