// flowsurf — Wavefront OBJ geometry (private to src/io). Read here rather than by
// vtkOBJReader: VTK 9.1 reads out of bounds (segfault) when a face names a texture
// coordinate or normal that does not exist ("f 1/5 2/5 3/5" with no vt lines), and
// takes letters for zeros. This parser checks every line and index.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace flowsurf::io::detail {

// Points from "v x y z", polygons from "f" lines (1-based or negative = relative
// vertex indices; "/texture/normal" parts ignored). Everything else (vt, vn, l, g, o,
// s, usemtl, mtllib, comments) is skipped: geometry only. Throws FormatError naming
// `path` and the line, IoError if the file cannot be read.
vtkSmartPointer<vtkPolyData> readObj(const std::string& path);

}  // namespace flowsurf::io::detail
