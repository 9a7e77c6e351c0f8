// flowsurf — our own PLY and OBJ parsers (private to src/io), used instead of VTK's: VTK
// 9.1's PLY code segfaults or aborts on malformed headers and truncated bodies, its OBJ
// reader reads out of bounds when a face names a texture coordinate or normal that does
// not exist ("f 1/5 2/5 3/5" with no vt lines), and both read letters as zeros. These check
// every count, index and value; they throw FormatError naming the file and the element or
// line, IoError if the file cannot be read. Geometry only.
#pragma once

#include <vtkSmartPointer.h>

#include <string>
#include <string_view>

class vtkPolyData;

namespace flowsurf::io::detail {

// Stanford PLY (ascii, binary little/big endian): points (x, y, z), point normals
// "Normals" when nx, ny, nz are all present, and polygons from the face element's
// vertex_indices (or vertex_index) list. Other elements and properties are parsed (to stay
// in step) and skipped.
vtkSmartPointer<vtkPolyData> readPly(const std::string& path);

// Wavefront OBJ: points from "v x y z", polygons from "f" lines (1-based or negative =
// relative vertex indices; "/texture/normal" parts ignored). Everything else (vt, vn, l,
// g, o, s, usemtl, mtllib, comments) is skipped.
vtkSmartPointer<vtkPolyData> readObj(const std::string& path);

// A bad token as these parsers and the legacy check quote it: its first 20 bytes, any byte
// that is not printable ASCII as '?'.
inline std::string shown(std::string_view token) {
    std::string s(token.substr(0, 20));
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) c = '?';
    return s;
}

}  // namespace flowsurf::io::detail
