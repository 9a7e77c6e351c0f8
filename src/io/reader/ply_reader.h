// flowsurf — Stanford PLY (ascii, binary little/big endian), private to src/io.
// Read here rather than by vtkPLYReader: VTK 9.1's PLY code segfaults or aborts on
// malformed headers and truncated bodies, and reads letters as zeros. This parser
// checks every count and value and throws FormatError naming the file and element.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace flowsurf::io::detail {

// Geometry only: points (x, y, z), point normals "Normals" when nx, ny, nz are all
// present, and polygons from the face element's vertex_indices (or vertex_index) list.
// Other elements and properties are parsed (to stay in step) and skipped.
vtkSmartPointer<vtkPolyData> readPly(const std::string& path);

}  // namespace flowsurf::io::detail
