// Sections: checked calls · the box's mesh and fields · expected surfaces as VTK legacy ·
// the cases.
#include "cgns_cases.h"

#include <cgns_io.h>
#include <cgnslib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>
#include <vector>

namespace flowsurf::testing_cgns {

namespace {

// --- checked calls -------------------------------------------------------------------
void check(int rc, const char* what) {
    if (rc != CG_OK) throw std::runtime_error(std::string("libcgns: ") + what + ": " + cg_get_error());
}

int openForWriting(const std::string& path, Backend backend) {
    check(cg_set_file_type(backend == Backend::Hdf5 ? CG_FILE_HDF5 : CG_FILE_ADF), "cg_set_file_type");
    int fn = 0;
    check(cg_open(path.c_str(), CG_MODE_WRITE, &fn), path.c_str());
    return fn;
}

void writeVector(int fn, int b, int z, int s, const char* name, const std::vector<double>* xyz) {
    int f = 0;
    for (int c = 0; c < 3; ++c) {
        const std::string n = std::string(name) + "XYZ"[c];
        check(cg_field_write(fn, b, z, s, CGNS_ENUMV(RealDouble), n.c_str(), xyz[c].data(), &f), n.c_str());
    }
}

// --- the box's mesh and fields ---------------------------------------------------------
constexpr int kNx = 4, kNy = 2, kNz = 2;
constexpr double kPi = 3.14159265358979323846;
constexpr double kLift = 0.5;  // a moving series' lift per unit time (z)

struct Point {
    double x, y, z;
};

// The velocity at time angle `theta` (0 for the steady cases); in-plane on the walls y = 0, 1.
Point velocity(const Point& p, double theta) {
    return {(0.5 + p.y) * std::cos(theta) + 0.2 * p.z, 0.1 * p.x, (0.5 + p.y) * std::sin(theta) + 0.3 * std::sin(kPi * p.x)};
}
double pressure(const Point& p) { return p.x + p.y * p.z; }

// One quadrilateral face of the box: its vertices (1-based CGNS ids) and the cell behind it.
struct Face {
    cgsize_t v[4];
    int cell;  // 0-based hexahedron index
};
struct Patch {
    const char* name;
    CGNS_ENUMT(BCType_t) type;
    const char* family;  // for FamilySpecified
    std::vector<Face> faces;
};

struct Box {
    std::vector<Point> points;
    std::vector<cgsize_t> hexa;
    std::vector<Patch> patches;
};

cgsize_t vid(int i, int j, int k) { return 1 + i + (kNx + 1) * (j + (kNy + 1) * k); }
int cellOf(int i, int j, int k) { return i + kNx * (j + kNy * k); }

Box makeBox() {
    Box box;
    for (int k = 0; k <= kNz; ++k)
        for (int j = 0; j <= kNy; ++j)
            for (int i = 0; i <= kNx; ++i) box.points.push_back({0.5 * i, 0.5 * j, 0.5 * k});
    for (int k = 0; k < kNz; ++k)
        for (int j = 0; j < kNy; ++j)
            for (int i = 0; i < kNx; ++i)
                for (cgsize_t v : {vid(i, j, k), vid(i + 1, j, k), vid(i + 1, j + 1, k), vid(i, j + 1, k),
                                   vid(i, j, k + 1), vid(i + 1, j, k + 1), vid(i + 1, j + 1, k + 1), vid(i, j + 1, k + 1)})
                    box.hexa.push_back(v);
    Patch inlet{"inlet", CGNS_ENUMV(BCInflow), nullptr, {}}, outlet{"outlet", CGNS_ENUMV(BCOutflow), nullptr, {}};
    for (int k = 0; k < kNz; ++k)
        for (int j = 0; j < kNy; ++j) {
            inlet.faces.push_back({{vid(0, j, k), vid(0, j, k + 1), vid(0, j + 1, k + 1), vid(0, j + 1, k)}, cellOf(0, j, k)});
            outlet.faces.push_back({{vid(kNx, j, k), vid(kNx, j + 1, k), vid(kNx, j + 1, k + 1), vid(kNx, j, k + 1)},
                                    cellOf(kNx - 1, j, k)});
        }
    Patch floor{"floor", CGNS_ENUMV(BCWall), nullptr, {}}, roof{"roof", CGNS_ENUMV(FamilySpecified), "Walls", {}};
    for (int k = 0; k < kNz; ++k)
        for (int i = 0; i < kNx; ++i) {
            floor.faces.push_back({{vid(i, 0, k), vid(i + 1, 0, k), vid(i + 1, 0, k + 1), vid(i, 0, k + 1)}, cellOf(i, 0, k)});
            roof.faces.push_back({{vid(i, kNy, k), vid(i, kNy, k + 1), vid(i + 1, kNy, k + 1), vid(i + 1, kNy, k)},
                                  cellOf(i, kNy - 1, k)});
        }
    Patch sides{"sides", CGNS_ENUMV(BCSymmetryPlane), nullptr, {}};
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i) {
            sides.faces.push_back({{vid(i, j, 0), vid(i, j + 1, 0), vid(i + 1, j + 1, 0), vid(i + 1, j, 0)}, cellOf(i, j, 0)});
            sides.faces.push_back(
                {{vid(i, j, kNz), vid(i + 1, j, kNz), vid(i + 1, j + 1, kNz), vid(i, j + 1, kNz)}, cellOf(i, j, kNz - 1)});
        }
    box.patches = {inlet, outlet, floor, roof, sides};
    return box;
}

double temperature(int cell) { return 300.0 + 2.0 * cell; }

// `mixed`: the hexahedra and all boundary faces in two MIXED sections, floor as an element
// list and roof as an ElementRange (the older names of face BCs), as polyhedral meshers write.
int writeMixedBoxZone(int fn, int b, const Box& box) {
    const cgsize_t cells = kNx * kNy * kNz;
    cgsize_t size[3] = {cgsize_t(box.points.size()), cells, 0};
    int z = 0, c = 0, s = 0;
    check(cg_zone_write(fn, b, "Fluid", size, CGNS_ENUMV(Unstructured), &z), "cg_zone_write");
    std::vector<double> xyz[3];
    for (const Point& p : box.points) xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z);
    for (int d = 0; d < 3; ++d)
        check(cg_coord_write(fn, b, z, CGNS_ENUMV(RealDouble), d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ",
                             xyz[d].data(), &c),
              "cg_coord_write");
    std::vector<cgsize_t> conn, offsets{0};
    for (cgsize_t e = 0; e < cells; ++e) {
        conn.push_back(CGNS_ENUMV(HEXA_8));
        conn.insert(conn.end(), box.hexa.begin() + 8 * e, box.hexa.begin() + 8 * (e + 1));
        offsets.push_back(cgsize_t(conn.size()));
    }
    check(cg_poly_section_write(fn, b, z, "Cells", CGNS_ENUMV(MIXED), 1, cells, 0, conn.data(), offsets.data(), &s), "Cells");
    conn.clear();
    offsets = {0};
    std::vector<std::vector<cgsize_t>> ids(box.patches.size());
    cgsize_t next = cells + 1;
    for (size_t p = 0; p < box.patches.size(); ++p)
        for (const Face& f : box.patches[p].faces) {
            conn.push_back(CGNS_ENUMV(QUAD_4));
            conn.insert(conn.end(), f.v, f.v + 4);
            offsets.push_back(cgsize_t(conn.size()));
            ids[p].push_back(next++);
        }
    check(cg_poly_section_write(fn, b, z, "Boundary", CGNS_ENUMV(MIXED), cells + 1, next - 1, 0, conn.data(), offsets.data(), &s),
          "Boundary");
    int f = 0, fbc = 0;
    check(cg_family_write(fn, b, "Walls", &f), "cg_family_write");
    check(cg_fambc_write(fn, b, f, "FamBC", CGNS_ENUMV(BCWallViscous), &fbc), "cg_fambc_write");
    for (size_t p = 0; p < box.patches.size(); ++p) {
        const Patch& patch = box.patches[p];
        const std::string name = patch.name;
        const cgsize_t range[2] = {ids[p].front(), ids[p].back()};
        int bc = 0;
        if (name == "floor")
            check(cg_boco_write(fn, b, z, patch.name, patch.type, CGNS_ENUMV(ElementList), cgsize_t(ids[p].size()),
                                ids[p].data(), &bc),
                  patch.name);
        else
            check(cg_boco_write(fn, b, z, patch.name, patch.type, CGNS_ENUMV(ElementRange), 2, range, &bc), patch.name);
        if (patch.family) {
            check(cg_goto(fn, b, "Zone_t", z, "ZoneBC_t", 1, "BC_t", bc, "end"), "cg_goto BC");
            check(cg_famname_write(patch.family), "cg_famname_write");
        }
    }
    return z;
}

// The box as polyhedra: every face once in an NGON_n section (the patches' faces first, so
// each BC is one element range), the cells as NFACE_n lists of signed face ids (negative:
// the face seen from its second cell), as Fluent's and STAR-CCM+'s exports are laid out.
int writePolyhedralBoxZone(int fn, int b, const Box& box) {
    const cgsize_t cells = kNx * kNy * kNz;
    cgsize_t size[3] = {cgsize_t(box.points.size()), cells, 0};
    int z = 0, c = 0, s = 0;
    check(cg_zone_write(fn, b, "Fluid", size, CGNS_ENUMV(Unstructured), &z), "cg_zone_write");
    std::vector<double> xyz[3];
    for (const Point& p : box.points) xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z);
    for (int d = 0; d < 3; ++d)
        check(cg_coord_write(fn, b, z, CGNS_ENUMV(RealDouble), d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ",
                             xyz[d].data(), &c),
              "cg_coord_write");
    std::vector<cgsize_t> faces, faceOffsets{0};
    std::map<std::vector<cgsize_t>, cgsize_t> faceId;  // sorted corners -> 1-based face element id
    auto addFace = [&](const cgsize_t* v) {
        std::vector<cgsize_t> key(v, v + 4);
        std::sort(key.begin(), key.end());
        auto [it, added] = faceId.try_emplace(key, cgsize_t(faceId.size()) + 1);
        if (added) {
            faces.insert(faces.end(), v, v + 4);
            faceOffsets.push_back(cgsize_t(faces.size()));
        }
        return std::pair{it->second, added};
    };
    std::vector<std::pair<cgsize_t, cgsize_t>> ranges;
    for (const Patch& patch : box.patches) {
        const cgsize_t first = cgsize_t(faceId.size()) + 1;
        for (const Face& f : patch.faces) addFace(f.v);
        ranges.emplace_back(first, cgsize_t(faceId.size()));
    }
    static const int kHexFaces[6][4] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {4, 5, 6, 7}};
    std::vector<cgsize_t> cellFaces, cellOffsets{0};
    for (cgsize_t e = 0; e < cells; ++e) {
        for (const auto& hf : kHexFaces) {
            const cgsize_t v[4] = {box.hexa[size_t(8 * e + hf[0])], box.hexa[size_t(8 * e + hf[1])],
                                   box.hexa[size_t(8 * e + hf[2])], box.hexa[size_t(8 * e + hf[3])]};
            const auto [id, added] = addFace(v);
            cellFaces.push_back(added ? id : -id);
        }
        cellOffsets.push_back(cgsize_t(cellFaces.size()));
    }
    const cgsize_t nfaces = cgsize_t(faceId.size());
    check(cg_poly_section_write(fn, b, z, "Faces", CGNS_ENUMV(NGON_n), 1, nfaces, 0, faces.data(), faceOffsets.data(), &s),
          "Faces");
    // Face ids in NFACE_n are the faces' element numbers; the cells come after them.
    check(cg_poly_section_write(fn, b, z, "Cells", CGNS_ENUMV(NFACE_n), nfaces + 1, nfaces + cells, 0, cellFaces.data(),
                                cellOffsets.data(), &s),
          "Cells");
    int f = 0, fbc = 0;
    check(cg_family_write(fn, b, "Walls", &f), "cg_family_write");
    check(cg_fambc_write(fn, b, f, "FamBC", CGNS_ENUMV(BCWallViscous), &fbc), "cg_fambc_write");
    for (size_t p = 0; p < box.patches.size(); ++p) {
        const Patch& patch = box.patches[p];
        const cgsize_t range[2] = {ranges[p].first, ranges[p].second};
        int bc = 0;
        check(cg_boco_write(fn, b, z, patch.name, patch.type, CGNS_ENUMV(PointRange), 2, range, &bc), patch.name);
        check(cg_boco_gridlocation_write(fn, b, z, bc, CGNS_ENUMV(FaceCenter)), patch.name);
        if (patch.family) {
            check(cg_goto(fn, b, "Zone_t", z, "ZoneBC_t", 1, "BC_t", bc, "end"), "cg_goto BC");
            check(cg_famname_write(patch.family), "cg_famname_write");
        }
    }
    return z;
}

// The box's zone: coordinates, the hexahedra and (`withBcs`) one face section and BC per patch.
int writeBoxZone(int fn, int b, const Box& box, bool withBcs) {
    const cgsize_t cells = kNx * kNy * kNz;
    cgsize_t size[3] = {cgsize_t(box.points.size()), cells, 0};
    int z = 0;
    check(cg_zone_write(fn, b, "Fluid", size, CGNS_ENUMV(Unstructured), &z), "cg_zone_write");
    std::vector<double> xyz[3];
    for (const Point& p : box.points) xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z);
    int c = 0;
    for (int d = 0; d < 3; ++d)
        check(cg_coord_write(fn, b, z, CGNS_ENUMV(RealDouble), d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ",
                             xyz[d].data(), &c),
              "cg_coord_write");
    int s = 0;
    check(cg_section_write(fn, b, z, "Hexahedra", CGNS_ENUMV(HEXA_8), 1, cells, 0, box.hexa.data(), &s), "cg_section_write");
    if (!withBcs) return z;
    cgsize_t next = cells + 1;
    bool familyWritten = false;
    for (const Patch& patch : box.patches) {
        std::vector<cgsize_t> quads;
        for (const Face& f : patch.faces) quads.insert(quads.end(), f.v, f.v + 4);
        const cgsize_t first = next, last = next + cgsize_t(patch.faces.size()) - 1;
        next = last + 1;
        check(cg_section_write(fn, b, z, patch.name, CGNS_ENUMV(QUAD_4), first, last, 0, quads.data(), &s), patch.name);
        const cgsize_t range[2] = {first, last};
        int bc = 0;
        if (patch.type == CGNS_ENUMV(BCOutflow)) {
            // The outlet as the list of its vertices, as some mesh generators write BCs.
            std::vector<cgsize_t> vertices;
            for (int k = 0; k <= kNz; ++k)
                for (int j = 0; j <= kNy; ++j) vertices.push_back(vid(kNx, j, k));
            check(cg_boco_write(fn, b, z, patch.name, patch.type, CGNS_ENUMV(PointList), cgsize_t(vertices.size()),
                                vertices.data(), &bc),
                  patch.name);
        } else {
            check(cg_boco_write(fn, b, z, patch.name, patch.type, CGNS_ENUMV(PointRange), 2, range, &bc), patch.name);
            check(cg_boco_gridlocation_write(fn, b, z, bc, CGNS_ENUMV(FaceCenter)), patch.name);
        }
        if (patch.family) {
            if (!familyWritten) {
                int f = 0, fbc = 0;
                check(cg_family_write(fn, b, patch.family, &f), "cg_family_write");
                check(cg_fambc_write(fn, b, f, "FamBC", CGNS_ENUMV(BCWallViscous), &fbc), "cg_fambc_write");
                familyWritten = true;
            }
            check(cg_goto(fn, b, "Zone_t", z, "ZoneBC_t", 1, "BC_t", bc, "end"), "cg_goto BC");
            check(cg_famname_write(patch.family), "cg_famname_write");
        }
    }
    return z;
}

void writeVertexSolution(int fn, int b, int z, const Box& box, const char* name, double theta) {
    int s = 0;
    check(cg_sol_write(fn, b, z, name, CGNS_ENUMV(Vertex), &s), name);
    std::vector<double> u[3], p;
    for (const Point& x : box.points) {
        const Point v = velocity(x, theta);
        u[0].push_back(v.x), u[1].push_back(v.y), u[2].push_back(v.z);
        p.push_back(pressure(x));
    }
    writeVector(fn, b, z, s, "Velocity", u);
    int f = 0;
    check(cg_field_write(fn, b, z, s, CGNS_ENUMV(RealDouble), "Pressure", p.data(), &f), "Pressure");
}

void writeCellSolution(int fn, int b, int z) {
    int s = 0, f = 0;
    check(cg_sol_write(fn, b, z, "CellCentred", CGNS_ENUMV(CellCenter), &s), "cg_sol_write CellCenter");
    std::vector<double> t;
    for (int c = 0; c < kNx * kNy * kNz; ++c) t.push_back(temperature(c));
    check(cg_field_write(fn, b, z, s, CGNS_ENUMV(RealDouble), "Temperature", t.data(), &f), "Temperature");
}

// --- expected surfaces as VTK legacy ------------------------------------------------------
// Quadrilaterals over their own points, with point vectors/scalars and cell scalars.
struct Surface {
    std::vector<Point> points;
    std::vector<std::vector<int>> quads;  // 0-based into points
    std::map<std::string, std::vector<Point>> pointVectors;
    std::map<std::string, std::vector<double>> pointScalars, cellScalars;
};

void writeLegacy(const std::string& path, const Surface& s) {
    std::ofstream out(path);
    out.precision(17);
    out << "# vtk DataFile Version 4.2\nexpected surface\nASCII\nDATASET POLYDATA\nPOINTS " << s.points.size() << " double\n";
    for (const Point& p : s.points) out << p.x << " " << p.y << " " << p.z << "\n";
    out << "POLYGONS " << s.quads.size() << " " << 5 * s.quads.size() << "\n";
    for (const auto& q : s.quads) out << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
    out << "POINT_DATA " << s.points.size() << "\n";
    for (const auto& [name, v] : s.pointVectors) {
        out << "VECTORS " << name << " double\n";
        for (const Point& p : v) out << p.x << " " << p.y << " " << p.z << "\n";
    }
    for (const auto& [name, v] : s.pointScalars) {
        out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
        for (double x : v) out << x << "\n";
    }
    if (!s.cellScalars.empty()) out << "CELL_DATA " << s.quads.size() << "\n";
    for (const auto& [name, v] : s.cellScalars) {
        out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
        for (double x : v) out << x << "\n";
    }
    if (!out) throw std::runtime_error("cannot write " + path);
}

// The box's faces of `patches` (all when empty) as a surface at time angle `theta`.
Surface boxSurface(const Box& box, const std::vector<std::string>& patches, double theta, bool cellData) {
    Surface s;
    std::map<cgsize_t, int> index;
    for (const Patch& patch : box.patches) {
        if (!patches.empty() && std::find(patches.begin(), patches.end(), patch.name) == patches.end()) continue;
        for (const Face& f : patch.faces) {
            std::vector<int> q;
            for (cgsize_t v : f.v) {
                auto [it, added] = index.try_emplace(v, int(s.points.size()));
                if (added) {
                    const Point& p = box.points[size_t(v - 1)];
                    s.points.push_back(p);
                    s.pointVectors["Velocity"].push_back(velocity(p, theta));
                    s.pointScalars["Pressure"].push_back(pressure(p));
                }
                q.push_back(it->second);
            }
            s.quads.push_back(q);
            if (cellData) s.cellScalars["Temperature"].push_back(temperature(f.cell));
        }
    }
    return s;
}

// --- the cases ------------------------------------------------------------------------------
int writeBase(int fn, const char* name) {
    int b = 0;
    check(cg_base_write(fn, name, 3, 3, &b), "cg_base_write");
    return b;
}

}  // namespace

void writeUnstructuredBox(const std::string& path, Backend backend, const std::string& expectedVtk) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    const int z = writeBoxZone(fn, b, box, true);
    writeVertexSolution(fn, b, z, box, "FlowSolution", 0.0);
    writeCellSolution(fn, b, z);
    check(cg_close(fn), "cg_close");
    if (!expectedVtk.empty()) writeLegacy(expectedVtk, boxSurface(box, {"floor", "roof"}, 0.0, true));
}

void writeMixedBox(const std::string& path, Backend backend, const std::string& expectedVtk) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    const int z = writeMixedBoxZone(fn, b, box);
    writeVertexSolution(fn, b, z, box, "FlowSolution", 0.0);
    writeCellSolution(fn, b, z);
    check(cg_close(fn), "cg_close");
    if (!expectedVtk.empty()) writeLegacy(expectedVtk, boxSurface(box, {"floor", "roof"}, 0.0, true));
}

void writeSurfaceZone(const std::string& path, Backend backend, const std::string& expectedVtk) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    int b = 0, z = 0, c = 0, s = 0;
    check(cg_base_write(fn, "Surface", 2, 3, &b), "cg_base_write");
    // The floor's faces over all of the box's points: a surface zone may carry unused points.
    const Patch& floor = box.patches[2];
    cgsize_t size[3] = {cgsize_t(box.points.size()), cgsize_t(floor.faces.size()), 0};
    check(cg_zone_write(fn, b, "Floor", size, CGNS_ENUMV(Unstructured), &z), "cg_zone_write");
    std::vector<double> xyz[3];
    for (const Point& p : box.points) xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z);
    for (int d = 0; d < 3; ++d)
        check(cg_coord_write(fn, b, z, CGNS_ENUMV(RealDouble), d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ",
                             xyz[d].data(), &c),
              "cg_coord_write");
    std::vector<cgsize_t> quads;
    for (const Face& f : floor.faces) quads.insert(quads.end(), f.v, f.v + 4);
    check(cg_section_write(fn, b, z, "Quads", CGNS_ENUMV(QUAD_4), 1, size[1], 0, quads.data(), &s), "cg_section_write");
    writeVertexSolution(fn, b, z, box, "FlowSolution", 0.0);
    check(cg_close(fn), "cg_close");
    if (!expectedVtk.empty()) writeLegacy(expectedVtk, boxSurface(box, {"floor"}, 0.0, false));
}

void writePolyhedralBox(const std::string& path, Backend backend, const std::string& expectedVtk) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    const int z = writePolyhedralBoxZone(fn, b, box);
    writeVertexSolution(fn, b, z, box, "FlowSolution", 0.0);
    writeCellSolution(fn, b, z);
    check(cg_close(fn), "cg_close");
    if (!expectedVtk.empty()) writeLegacy(expectedVtk, boxSurface(box, {"floor", "roof"}, 0.0, true));
}

void writeBoxWithoutBcs(const std::string& path, Backend backend, const std::string& expectedVtk) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    const int z = writeBoxZone(fn, b, box, false);
    writeVertexSolution(fn, b, z, box, "FlowSolution", 0.0);
    check(cg_close(fn), "cg_close");
    if (!expectedVtk.empty()) writeLegacy(expectedVtk, boxSurface(box, {}, 0.0, false));
}

void writeUnstructuredSeries(const std::string& path, Backend backend, const std::string& expectedVtkPattern, bool moving) {
    const Box box = makeBox();
    const double times[3] = {0.0, 0.5, 1.0};
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    check(cg_simulation_type_write(fn, b, CGNS_ENUMV(TimeAccurate)), "cg_simulation_type_write");
    const int z = writeBoxZone(fn, b, box, true);
    char pointers[3][32];
    for (int t = 0; t < 3; ++t) {
        char name[33];
        std::snprintf(name, sizeof name, "Solution%d", t);
        writeVertexSolution(fn, b, z, box, name, times[t] * kPi / 2);
        std::memset(pointers[t], ' ', 32);  // blank-padded, not terminated, as the standard stores names
        std::memcpy(pointers[t], name, std::strlen(name));
    }
    check(cg_biter_write(fn, b, "TimeIterValues", 3), "cg_biter_write");
    check(cg_goto(fn, b, "BaseIterativeData_t", 1, "end"), "cg_goto BaseIterativeData");
    const cgsize_t steps = 3;
    check(cg_array_write("TimeValues", CGNS_ENUMV(RealDouble), 1, &steps, times), "TimeValues");
    // A moving mesh: each step's coordinates in a GridCoordinates_t of its own, the box
    // lifted by kLift * t (the first step keeps the zone's GridCoordinates).
    char grids[3][32];
    for (int t = 0; t < 3 && moving; ++t) {
        std::memset(grids[t], ' ', 32);
        const std::string name = t == 0 ? "GridCoordinates" : "Grid" + std::to_string(t);
        std::memcpy(grids[t], name.data(), name.size());
        if (t == 0) continue;
        int g = 0;
        check(cg_grid_write(fn, b, z, name.c_str(), &g), "cg_grid_write");
        check(cg_goto(fn, b, "Zone_t", z, "GridCoordinates_t", g, "end"), "cg_goto grid");
        std::vector<double> xyz[3];
        for (const Point& p : box.points) xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z + kLift * times[t]);
        const cgsize_t n = cgsize_t(box.points.size());
        for (int d = 0; d < 3; ++d)
            check(cg_array_write(d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ", CGNS_ENUMV(RealDouble), 1, &n,
                                 xyz[d].data()),
                  "moving coordinates");
    }
    check(cg_ziter_write(fn, b, z, "ZoneIterativeData"), "cg_ziter_write");
    check(cg_goto(fn, b, "Zone_t", z, "ZoneIterativeData_t", 1, "end"), "cg_goto ZoneIterativeData");
    const cgsize_t dims[2] = {32, 3};
    check(cg_array_write("FlowSolutionPointers", CGNS_ENUMV(Character), 2, dims, pointers), "FlowSolutionPointers");
    if (moving) check(cg_array_write("GridCoordinatesPointers", CGNS_ENUMV(Character), 2, dims, grids), "GridCoordinatesPointers");
    check(cg_close(fn), "cg_close");
    for (int t = 0; t < 3 && !expectedVtkPattern.empty(); ++t) {
        char file[4096];
        std::snprintf(file, sizeof file, expectedVtkPattern.c_str(), t);
        writeLegacy(file, boxSurface(box, {"floor", "roof"}, times[t] * kPi / 2, false));
    }
}

void writeStructuredBlocks(const std::string& path, Backend backend, const std::string& expectedVtk) {
    constexpr int ni = 5, nj = 4, nk = 3;
    auto at = [](int i, int j, int k, double x0) {
        const double x = x0 + 0.25 * i;
        return Point{x, 0.2 * j + 0.05 * std::sin(kPi * x) * (1.0 - j / double(nj - 1)), 0.25 * k};
    };
    auto flow = [](const Point& p) { return Point{1.0 + p.y, 0.0, 0.5 * std::sin(kPi * p.x)}; };
    auto density = [](int cell, double x0) { return 1.0 + 0.1 * cell + x0; };
    Surface expected;
    const int fn = openForWriting(path, backend);
    const struct {
        const char* base;
        const char* zone;
        double x0;
    } zones[] = {{"Left", "Block1", 0.0}, {"Left", "Block2", 1.0}, {"Right", "Block3", 2.0}};
    int b = 0;
    std::string lastBase;
    for (const auto& zone : zones) {
        if (zone.base != lastBase) b = writeBase(fn, zone.base), lastBase = zone.base;
        cgsize_t size[9] = {ni, nj, nk, ni - 1, nj - 1, nk - 1, 0, 0, 0};
        int z = 0, c = 0, s = 0, f = 0, bc = 0;
        check(cg_zone_write(fn, b, zone.zone, size, CGNS_ENUMV(Structured), &z), "cg_zone_write");
        std::vector<double> xyz[3], u[3];
        for (int k = 0; k < nk; ++k)
            for (int j = 0; j < nj; ++j)
                for (int i = 0; i < ni; ++i) {  // i fastest, as the standard orders vertices
                    const Point p = at(i, j, k, zone.x0), v = flow(p);
                    xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z);
                    u[0].push_back(v.x), u[1].push_back(v.y), u[2].push_back(v.z);
                }
        for (int d = 0; d < 3; ++d)
            check(cg_coord_write(fn, b, z, CGNS_ENUMV(RealDouble), d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ",
                                 xyz[d].data(), &c),
                  "cg_coord_write");
        check(cg_sol_write(fn, b, z, "FlowSolution", CGNS_ENUMV(Vertex), &s), "cg_sol_write");
        writeVector(fn, b, z, s, "Velocity", u);
        std::vector<double> rho;
        for (int c = 0; c < (ni - 1) * (nj - 1) * (nk - 1); ++c) rho.push_back(density(c, zone.x0));
        check(cg_sol_write(fn, b, z, "CellCentred", CGNS_ENUMV(CellCenter), &s), "cg_sol_write CellCenter");
        check(cg_field_write(fn, b, z, s, CGNS_ENUMV(RealDouble), "Density", rho.data(), &f), "Density");
        const cgsize_t wall[6] = {1, 1, 1, ni, 1, nk}, far[6] = {1, nj, 1, ni, nj, nk};
        check(cg_boco_write(fn, b, z, "wall", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointRange), 2, wall, &bc), "wall");
        check(cg_boco_write(fn, b, z, "farfield", CGNS_ENUMV(BCFarfield), CGNS_ENUMV(PointRange), 2, far, &bc), "farfield");
        const int first = int(expected.points.size());
        for (int k = 0; k < nk; ++k)
            for (int i = 0; i < ni; ++i) {
                const Point p = at(i, 0, k, zone.x0);
                expected.points.push_back(p);
                expected.pointVectors["Velocity"].push_back(flow(p));
            }
        for (int k = 0; k + 1 < nk; ++k)
            for (int i = 0; i + 1 < ni; ++i) {
                expected.quads.push_back({first + i + ni * k, first + i + 1 + ni * k, first + i + 1 + ni * (k + 1),
                                          first + i + ni * (k + 1)});
                expected.cellScalars["Density"].push_back(density(i + (ni - 1) * (nj - 1) * k, zone.x0));  // cell (i, 1, k)
            }
    }
    check(cg_close(fn), "cg_close");
    if (!expectedVtk.empty()) writeLegacy(expectedVtk, expected);
}

namespace {

// The box's points as one structured zone (vid's order is the standard's, i fastest) with
// floor, roof and inlet as vertex ranges.
int writeStructuredBoxZone(int fn, int b, const Box& box) {
    cgsize_t size[9] = {kNx + 1, kNy + 1, kNz + 1, kNx, kNy, kNz, 0, 0, 0};
    int z = 0, c = 0, bc = 0;
    check(cg_zone_write(fn, b, "Fluid", size, CGNS_ENUMV(Structured), &z), "cg_zone_write");
    std::vector<double> xyz[3];
    for (const Point& p : box.points) xyz[0].push_back(p.x), xyz[1].push_back(p.y), xyz[2].push_back(p.z);
    for (int d = 0; d < 3; ++d)
        check(cg_coord_write(fn, b, z, CGNS_ENUMV(RealDouble), d == 0 ? "CoordinateX" : d == 1 ? "CoordinateY" : "CoordinateZ",
                             xyz[d].data(), &c),
              "cg_coord_write");
    const cgsize_t floor[6] = {1, 1, 1, kNx + 1, 1, kNz + 1}, roof[6] = {1, kNy + 1, 1, kNx + 1, kNy + 1, kNz + 1},
                   inlet[6] = {1, 1, 1, 1, kNy + 1, kNz + 1};
    check(cg_boco_write(fn, b, z, "floor", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointRange), 2, floor, &bc), "floor");
    check(cg_boco_write(fn, b, z, "roof", CGNS_ENUMV(BCWall), CGNS_ENUMV(PointRange), 2, roof, &bc), "roof");
    check(cg_boco_write(fn, b, z, "inlet", CGNS_ENUMV(BCInflow), CGNS_ENUMV(PointRange), 2, inlet, &bc), "inlet");
    return z;
}

}  // namespace

void writeCouetteBox(const std::string& path, Backend backend, CouetteVelocity velocity, bool structured) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    const int z = structured ? writeStructuredBoxZone(fn, b, box) : writeBoxZone(fn, b, box, true);
    int s = 0, f = 0;
    std::vector<double> u[3], p;
    if (velocity == CouetteVelocity::CellCenter) {
        check(cg_sol_write(fn, b, z, "CellCentred", CGNS_ENUMV(CellCenter), &s), "cg_sol_write CellCenter");
        for (int k = 0; k < kNz; ++k)
            for (int j = 0; j < kNy; ++j)
                for (int i = 0; i < kNx; ++i)  // cellOf's order
                    u[0].push_back(kCouetteShear * 0.5 * (j + 0.5)), u[1].push_back(0.0), u[2].push_back(0.0);
    } else {
        check(cg_sol_write(fn, b, z, "FlowSolution", CGNS_ENUMV(Vertex), &s), "cg_sol_write");
        for (const Point& x : box.points) u[0].push_back(kCouetteShear * x.y), u[1].push_back(0.0), u[2].push_back(0.0);
    }
    for (const Point& x : box.points) p.push_back(pressure(x));
    if (velocity != CouetteVelocity::None) writeVector(fn, b, z, s, "Velocity", u);
    else check(cg_field_write(fn, b, z, s, CGNS_ENUMV(RealDouble), "Pressure", p.data(), &f), "Pressure");
    check(cg_close(fn), "cg_close");
}

void overwriteNode(const std::string& path, const std::string& node, const std::vector<int>& values) {
    int cgio = 0;
    double root = 0, id = 0;
    auto checkIo = [&](int rc, const char* what) {
        if (rc != CG_OK) {
            char message[CGIO_MAX_ERROR_LENGTH + 1] = {};
            cgio_error_message(message);
            throw std::runtime_error(path + ": " + what + " " + node + ": " + message);
        }
    };
    checkIo(cgio_open_file(path.c_str(), CGIO_MODE_MODIFY, CGIO_FILE_NONE, &cgio), "cgio_open_file");
    checkIo(cgio_get_root_id(cgio, &root), "cgio_get_root_id");
    checkIo(cgio_get_node_id(cgio, root, node.c_str(), &id), "cgio_get_node_id");
    checkIo(cgio_write_all_data(cgio, id, values.data()), "cgio_write_all_data");
    checkIo(cgio_close_file(cgio), "cgio_close_file");
}

void writeLinkedBox(const std::string& path, Backend backend, const std::string& target, const std::string& targetNode) {
    const Box box = makeBox();
    const int fn = openForWriting(path, backend);
    const int b = writeBase(fn, "Base");
    const cgsize_t size[3] = {cgsize_t(box.points.size()), kNx * kNy * kNz, 0};
    int z = 0, s = 0;
    check(cg_zone_write(fn, b, "Fluid", size, CGNS_ENUMV(Unstructured), &z), "cg_zone_write");
    check(cg_goto(fn, b, "Zone_t", z, "end"), "cg_goto zone");
    check(cg_link_write("GridCoordinates", target.c_str(), targetNode.c_str()), "cg_link_write");
    check(cg_section_write(fn, b, z, "Hexahedra", CGNS_ENUMV(HEXA_8), 1, size[1], 0, box.hexa.data(), &s), "cg_section_write");
    check(cg_close(fn), "cg_close");
}

}  // namespace flowsurf::testing_cgns
