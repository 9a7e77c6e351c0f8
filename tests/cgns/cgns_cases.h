// Small CGNS cases written with Debian's libcgns, each with the surface flowsurf should
// read from it written beside it as a VTK legacy file built from the same points and
// formulas (no CGNS or VTK reader involved), so a test can compare the two readings.
#pragma once

#include <string>
#include <vector>

namespace flowsurf::testing_cgns {

enum class Backend { Hdf5, Adf };

// A hexahedral box [0,2]x[0,1]x[0,1] (4x2x2 cells) as one unstructured zone, with
// quadrilateral boundary sections and one BC per side: inlet (BCInflow), outlet (BCOutflow,
// given as the list of its vertices; the others as ranges of face elements),
// floor (BCWall), roof (FamilySpecified, family "Walls" whose BC is BCWallViscous) and the
// two sides (BCSymmetryPlane). Solutions: Velocity and Pressure at the vertices,
// Temperature at the cell centres. Expected surface (`expectedVtk`): floor + roof, with
// Velocity, Pressure and Temperature (each wall face's cell's value, as cell data).
void writeUnstructuredBox(const std::string& path, Backend backend, const std::string& expectedVtk = {});

// The same box and solutions with its cells and boundary faces in two MIXED sections, the
// floor BC as an ElementList and the others as ElementRanges. Expected surface: as above.
void writeMixedBox(const std::string& path, Backend backend, const std::string& expectedVtk = {});

// The same box and solutions as polyhedra: all faces in an NGON_n section, the cells as
// NFACE_n, each BC a range of NGON_n faces. Expected surface: as above.
void writePolyhedralBox(const std::string& path, Backend backend, const std::string& expectedVtk = {});

// The same box's mesh with three time steps (BaseIterativeData t = 0, 0.5, 1 and
// ZoneIterativeData's FlowSolutionPointers): the velocity turns with time. `moving`: the
// mesh rises by 0.5 t along z (GridCoordinatesPointers to one GridCoordinates_t per step).
// `expectedVtk`: a printf pattern ("%d": step) for the wall surface of each step, unmoved.
void writeUnstructuredSeries(const std::string& path, Backend backend, const std::string& expectedVtkPattern = {},
                             bool moving = false);

// Two bases of structured (curvilinear) zones, three zones in all, with a BCWall on each
// zone's j = 1 face and a BCFarfield on its j = max face; Velocity at the vertices, Density
// at the cell centres. Expected surface: the three j = 1 faces (Density of the cells on them).
void writeStructuredBlocks(const std::string& path, Backend backend, const std::string& expectedVtk = {});

// A surface zone (a base of cell dimension 2): the box's floor as quadrilaterals over all the
// box's points, Velocity and Pressure at the vertices. Expected surface: the floor.
void writeSurfaceZone(const std::string& path, Backend backend, const std::string& expectedVtk = {});

// A volume without any BC: the expected surface is the box's whole boundary (6 sides).
void writeBoxWithoutBcs(const std::string& path, Backend backend, const std::string& expectedVtk = {});

// The box with an exact linear shear u = (kCouetteShear * y, 0, 0) (plane Couette flow between
// the floor at rest and the roof moving at kCouetteShear), as one unstructured zone with
// writeUnstructuredBox's BCs or (`structured`) one structured zone of the same points with
// BCWall floor (j = 1) and roof (j = max) and a BCInflow inlet (i = 1). The velocity is a
// Vertex solution, a CellCenter one (the cells' centre values: the roof's own velocity is then
// unknown) or absent (a Pressure only). The one-cell wall stress is exact for a linear profile:
// ν·kCouetteShear along x on the floor, −ν·kCouetteShear on the moving roof, and with the roof
// taken at rest (cell-centred) ν·(0.75 kCouetteShear)/0.25 = 3ν·kCouetteShear.
inline constexpr double kCouetteShear = 2.0;
enum class CouetteVelocity { Vertex, CellCenter, None };
void writeCouetteBox(const std::string& path, Backend backend, CouetteVelocity velocity, bool structured);

// Hostile variants of a file written by writeUnstructuredBox, damaged in place through
// libcgns's node layer: `node` ("/Base/Fluid" the zone's sizes, "/Base/Fluid/floor/ElementRange"
// a section's range, "/Base/Fluid/ZoneBC/floor/PointRange" a BC's) overwritten with the
// two or three 32-bit `values`.
void overwriteNode(const std::string& path, const std::string& node, const std::vector<int>& values);

// The box with its coordinates a link to `target` (a file name, relative to the box's
// folder, or absolute) at node `targetNode`: a missing file, a node that is not there, a
// file outside the folder or the box itself.
void writeLinkedBox(const std::string& path, Backend backend, const std::string& target, const std::string& targetNode);

}  // namespace flowsurf::testing_cgns
