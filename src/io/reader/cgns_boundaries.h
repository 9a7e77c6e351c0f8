// flowsurf — a CGNS file's zones and boundary conditions, read with libcgns in the reader
// process (private to src/io). VTK 9.1's vtkCGNSReader reads the zones and solutions but
// loads only FamilySpecified BCs of unstructured zones as patches (every other BC type is
// "not supported yet", structured zones none at all), so the patches are taken from here:
// each BC's name, type, family and faces, as ids of the zone's vertices (0-based, the
// order vtkCGNSReader gives its points in). Every count is checked against the zone's
// sizes and the file's size before anything is allocated for it.
#pragma once

#include <vtkType.h>

#include <string>
#include <vector>

namespace flowsurf::io::detail {

// The faces of one boundary condition: polygons over the zone's vertices, in VTK's cell
// array layout (offsets.size() == faces + 1).
struct CgnsPatch {
    std::string name;        // the BC_t node's name
    std::string type;        // its BCType_t ("BCWall"), the family's when FamilySpecified
    std::string family;      // its FamilyName, if any
    std::vector<vtkIdType> offsets{0}, ids;
    size_t faceCount() const { return offsets.size() - 1; }
};

struct CgnsZone {
    std::string base, name;
    bool structured = false;
    int cellDim = 3;                  // the base's cell dimension: 3 volume, 2 surface
    vtkIdType vertices = 0, cells = 0;
    int size[3] = {0, 0, 0};          // structured: vertices along i, j, k
    std::vector<CgnsPatch> patches;
};

// Opens `path` with libcgns read-only and reads every base's zones and BCs. Throws
// FormatError naming the file (and the base, zone, BC) when it is not CGNS or a count or
// index is out of range.
std::vector<CgnsZone> readCgnsZones(const std::string& path);

// Whether a BC type is a solid wall: the body a wall-flow texture is drawn on (inviscid
// walls included: an Euler solution's body).
bool isCgnsWallType(const std::string& type);

}  // namespace flowsurf::io::detail
