// Sections: arrays and units · wall faces to volume cells · the one-cell wall gradient ·
// addSkinFriction · boundary surfaces of volume files.
#include "io/reader/skin_friction.h"

#include "core/errors.h"

#include <vtkCellType.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <unordered_map>

namespace flowsurf::io::detail {

namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// --- arrays and units ------------------------------------------------------------------

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool isVelocityName(const char* name) {
    if (!name) return false;
    const std::string n = lower(name);
    return n == "u" || n == "velocity" || n == "vel";
}

// A 3-component array `name` of `fd`, or null.
vtkDataArray* vectorArray(vtkFieldData* fd, const std::string& name) {
    if (name.empty()) return nullptr;
    vtkDataArray* a = fd->GetArray(name.c_str());
    return a && a->GetNumberOfComponents() == 3 ? a : nullptr;
}

std::string vectorArrayList(vtkDataSet* data) {
    std::string list;
    for (vtkFieldData* fd : {static_cast<vtkFieldData*>(data->GetCellData()), static_cast<vtkFieldData*>(data->GetPointData())})
        for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
            if (vtkDataArray* a = fd->GetArray(i); a && a->GetName() && a->GetNumberOfComponents() == 3)
                list += (list.empty() ? "" : ", ") + std::string(a->GetName());
    return list.empty() ? "none" : list;
}

// --- wall faces to volume cells ----------------------------------------------------------
// Points are matched by their exact coordinates: a patch read apart from its volume
// (OpenFOAM, CGNS) holds copies of the volume's points, and a decomposed case's appended
// pieces hold one copy per processor, so one coordinate may name several volume points.
struct Key {
    double x, y, z;
    bool operator==(const Key& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct KeyHash {
    size_t operator()(const Key& k) const {
        uint64_t b[3];
        std::memcpy(b, &k, sizeof b);
        return size_t(b[0] * 0x9E3779B97F4A7C15ull ^ (b[1] + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full ^ b[2]);
    }
};
using PointMatches = std::unordered_map<Key, std::vector<vtkIdType>, KeyHash>;

Key keyOf(vtkPoints* points, vtkIdType id) {
    double p[3];
    points->GetPoint(id, p);
    return {p[0] + 0.0, p[1] + 0.0, p[2] + 0.0};  // + 0.0: -0 and 0 hash alike
}

// The volume points at each wall point's coordinates.
PointMatches matchPoints(vtkDataSet* volume, const std::vector<vtkPolyData*>& walls) {
    PointMatches matches;
    for (vtkPolyData* w : walls)
        for (vtkIdType i = 0; i < w->GetNumberOfPoints(); ++i) matches.try_emplace(keyOf(w->GetPoints(), i));
    double p[3];
    for (vtkIdType i = 0; i < volume->GetNumberOfPoints(); ++i) {
        volume->GetPoint(i, p);
        if (auto it = matches.find(Key{p[0] + 0.0, p[1] + 0.0, p[2] + 0.0}); it != matches.end()) it->second.push_back(i);
    }
    return matches;
}

// Whether a cell of `type` fills a volume (VTK's 3-D linear, quadratic, higher-order and
// polyhedral cells), from the type alone: building a vtkPolyhedron per test would be slow.
bool isVolumeCell(int type) {
    switch (type) {
    case VTK_TETRA: case VTK_VOXEL: case VTK_HEXAHEDRON: case VTK_WEDGE: case VTK_PYRAMID:
    case VTK_PENTAGONAL_PRISM: case VTK_HEXAGONAL_PRISM: case VTK_QUADRATIC_TETRA: case VTK_QUADRATIC_HEXAHEDRON:
    case VTK_QUADRATIC_WEDGE: case VTK_QUADRATIC_PYRAMID: case VTK_TRIQUADRATIC_HEXAHEDRON:
    case VTK_QUADRATIC_LINEAR_WEDGE: case VTK_BIQUADRATIC_QUADRATIC_WEDGE: case VTK_BIQUADRATIC_QUADRATIC_HEXAHEDRON:
    case VTK_TRIQUADRATIC_PYRAMID: case VTK_CONVEX_POINT_SET: case VTK_POLYHEDRON: case VTK_LAGRANGE_TETRAHEDRON:
    case VTK_LAGRANGE_HEXAHEDRON: case VTK_LAGRANGE_WEDGE: case VTK_LAGRANGE_PYRAMID: case VTK_BEZIER_TETRAHEDRON:
    case VTK_BEZIER_HEXAHEDRON: case VTK_BEZIER_WEDGE: case VTK_BEZIER_PYRAMID:
        return true;
    default:
        return false;
    }
}

// The 3-D volume cell holding every point of a wall face (`faceMatches`: the volume points
// at each face point), or -1.
vtkIdType ownerCell(vtkDataSet* volume, const std::vector<const std::vector<vtkIdType>*>& faceMatches,
                    vtkIdList* cells, vtkIdList* cellPoints) {
    for (vtkIdType first : *faceMatches[0]) {
        volume->GetPointCells(first, cells);
        for (vtkIdType k = 0; k < cells->GetNumberOfIds(); ++k) {
            const vtkIdType c = cells->GetId(k);
            if (!isVolumeCell(volume->GetCellType(c))) continue;
            volume->GetCellPoints(c, cellPoints);
            auto inCell = [&](const std::vector<vtkIdType>* ids) {
                for (vtkIdType id : *ids)
                    if (cellPoints->IsId(id) >= 0) return true;
                return false;
            };
            if (std::all_of(faceMatches.begin() + 1, faceMatches.end(), inCell)) return c;
        }
    }
    return -1;
}

// --- the one-cell wall gradient ------------------------------------------------------------

// The mean of `values` (or of the points' coordinates when null) over `ids`.
Vec meanOver(vtkDataSet* data, vtkIdList* ids, vtkDataArray* values) {
    Vec m{0, 0, 0};
    double t[3];
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
        if (values) values->GetTuple(ids->GetId(k), t);
        else data->GetPoint(ids->GetId(k), t);
        for (int a = 0; a < 3; ++a) m[a] += t[a];
    }
    const double n = double(std::max<vtkIdType>(1, ids->GetNumberOfIds()));
    return {m[0] / n, m[1] / n, m[2] / n};
}

// A polygon's centroid (of its points) and unit normal (Newell's sum, robust for
// non-planar quads); the normal's length is 0 for a degenerate face.
void faceFrame(vtkPolyData* wall, vtkIdType face, Vec& centre, Vec& normal) {
    vtkIdType n;
    const vtkIdType* ids;
    wall->GetCellPoints(face, n, ids);
    centre = {0, 0, 0};
    normal = {0, 0, 0};
    for (vtkIdType k = 0; k < n; ++k) {
        double a[3], b[3];
        wall->GetPoint(ids[k], a);
        wall->GetPoint(ids[(k + 1) % n], b);
        normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
        normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
        normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
        for (int c = 0; c < 3; ++c) centre[c] += a[c] / double(n);
    }
    const double len = std::sqrt(dot(normal, normal));
    for (double& c : normal) c = len > 0 ? c / len : 0.0;
}

// What one wall face needs besides the geometry: the velocities and viscosities that apply.
struct WallArrays {
    vtkDataArray* cellVelocity = nullptr;   // the volume's, per cell ...
    vtkDataArray* pointVelocity = nullptr;  // ... or per point
    vtkDataArray* wallVelocity = nullptr;   // the wall's own, per face
    vtkDataArray* turbulentViscosity = nullptr;
};

// Lists reused from face to face.
struct Scratch {
    vtkSmartPointer<vtkIdList> cells = vtkSmartPointer<vtkIdList>::New();
    vtkSmartPointer<vtkIdList> cellPoints = vtkSmartPointer<vtkIdList>::New();
    vtkSmartPointer<vtkIdList> facePoints = vtkSmartPointer<vtkIdList>::New();
};

// τ on wall face f of `wall` with owner cell c (the header's formula); zero for a degenerate
// face. Throws FormatError (`where` names the face) when c's centre lies on the face's plane.
Vec faceStress(vtkDataSet* volume, vtkPolyData* wall, vtkIdType f, vtkIdType c,
               const std::vector<const std::vector<vtkIdType>*>& faceMatches, const WallArrays& arrays, double nu,
               Scratch& scratch, const std::string& where) {
    vtkIdList* cellPoints = scratch.cellPoints;
    vtkIdList* facePoints = scratch.facePoints;
    Vec xf, normal;
    faceFrame(wall, f, xf, normal);
    if (dot(normal, normal) == 0) return {0, 0, 0};  // a degenerate face, dropped with the surface's checks
    volume->GetCellPoints(c, cellPoints);
    const Vec xc = meanOver(volume, cellPoints, nullptr);
    double d = dot(normal, sub(xc, xf));
    if (d < 0) {
        for (double& v : normal) v = -v;
        d = -d;
    }
    // A centre on the face's plane (a cell flat against its wall face) has no gradient to give;
    // relative to the centre's offset, so that a tiny cell is not taken for a flat one.
    const Vec diagonal = sub(xc, xf);
    if (!(d > 1e-9 * std::sqrt(dot(diagonal, diagonal))) || !(d > 0))
        throw FormatError(where + " lies at zero distance from the centre of its volume cell " + std::to_string(c));
    // (1) the velocity next to the wall and the wall's own
    Vec uc{0, 0, 0}, uw{0, 0, 0};
    if (arrays.cellVelocity) arrays.cellVelocity->GetTuple(c, uc.data());
    else uc = meanOver(volume, cellPoints, arrays.pointVelocity);
    if (arrays.wallVelocity) {
        arrays.wallVelocity->GetTuple(f, uw.data());
    } else if (arrays.pointVelocity) {
        facePoints->Reset();
        for (const auto* m : faceMatches)
            for (vtkIdType id : *m)
                if (cellPoints->IsId(id) >= 0) {
                    facePoints->InsertNextId(id);
                    break;
                }
        uw = meanOver(volume, facePoints, arrays.pointVelocity);
    }
    // (2) its tangential part over the wall distance, (3) times the viscosity
    const Vec du = sub(uc, uw);
    const double normalPart = dot(du, normal);
    const double nuEff = nu + (arrays.turbulentViscosity ? arrays.turbulentViscosity->GetComponent(f, 0) : 0.0);
    return {nuEff * (du[0] - normalPart * normal[0]) / d, nuEff * (du[1] - normalPart * normal[1]) / d,
            nuEff * (du[2] - normalPart * normal[2]) / d};
}

}  // namespace

std::string skinFrictionUnits(double viscosity) {
    return viscosity > 0 ? "m2/s2" : "1/s, relative: no viscosity given";
}

std::string findVelocityArray(vtkDataSet* volume) {
    for (vtkFieldData* fd : {static_cast<vtkFieldData*>(volume->GetCellData()), static_cast<vtkFieldData*>(volume->GetPointData())})
        for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
            if (vtkDataArray* a = fd->GetArray(i); a && a->GetNumberOfComponents() == 3 && isVelocityName(a->GetName()))
                return a->GetName();
    return {};
}

bool hasVolumeCells(vtkDataSet* data) {
    for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
        if (isVolumeCell(data->GetCellType(c))) return true;
    return false;
}

// --- addSkinFriction ------------------------------------------------------------------------
namespace {

// The volume's velocity arrays, checked: the cell's own value where there is one; point values
// (on the wall: the wall's velocity, a moving wall's included) give the wall's velocity, and
// the cell's without cell values.
WallArrays volumeVelocity(vtkDataSet* volume, const SkinFrictionOptions& options, const std::string& what) {
    const std::string velocity = options.velocity.empty() ? findVelocityArray(volume) : options.velocity;
    WallArrays arrays;
    arrays.cellVelocity = vectorArray(volume->GetCellData(), velocity);
    arrays.pointVelocity = vectorArray(volume->GetPointData(), velocity);
    if (!arrays.cellVelocity && !arrays.pointVelocity)
        throw FieldError(what + ": the volume has no velocity " +
                         (velocity.empty() ? "(a 3-component array named U, velocity or vel)" : "'" + velocity + "'") +
                         " to take the wall gradient of (its vector arrays: " + vectorArrayList(volume) + ")");
    if (!hasVolumeCells(volume)) throw FormatError(what + ": the data set has no volume cells next to the walls");
    return arrays;
}

// The volume cell behind wall face f (-1: none), with `faceMatches` set to the volume points
// at each of the face's points.
using OwnerOf = std::function<vtkIdType(vtkIdType f, std::vector<const std::vector<vtkIdType>*>& faceMatches)>;

// Adds kSkinFrictionName to one wall; returns how many of its faces have no owner cell (zero
// there, said in one warning).
size_t addWallStress(vtkDataSet* volume, vtkPolyData* wall, const std::string& wallName, WallArrays arrays,
                     const SkinFrictionOptions& options, const std::string& what, const OwnerOf& ownerOf) {
    arrays.wallVelocity = vectorArray(wall->GetCellData(), options.wallVelocity);
    vtkDataArray* nut = options.turbulentViscosity.empty() || options.viscosity <= 0
                            ? nullptr
                            : wall->GetCellData()->GetArray(options.turbulentViscosity.c_str());
    arrays.turbulentViscosity = nut && nut->GetNumberOfComponents() == 1 ? nut : nullptr;
    const double nu = options.viscosity > 0 ? options.viscosity : 1.0;
    auto tau = vtkSmartPointer<vtkDoubleArray>::New();
    tau->SetName(kSkinFrictionName);
    tau->SetNumberOfComponents(3);
    tau->SetNumberOfTuples(wall->GetNumberOfCells());
    tau->Fill(0.0);
    Scratch scratch;
    size_t unmatched = 0;
    std::vector<const std::vector<vtkIdType>*> faceMatches;
    for (vtkIdType f = 0; f < wall->GetNumberOfCells(); ++f) {
        vtkIdType n;
        const vtkIdType* ids;
        wall->GetCellPoints(f, n, ids);
        if (n < 3) continue;  // lines and vertices bound no cell
        faceMatches.clear();
        const vtkIdType c = ownerOf(f, faceMatches);
        if (c < 0) {
            ++unmatched;
            continue;
        }
        const std::string where = what + ": face " + std::to_string(f) + " of " + wallName;
        const Vec t = faceStress(volume, wall, f, c, faceMatches, arrays, nu, scratch, where);
        for (int a = 0; a < 3; ++a) tau->SetComponent(f, a, t[a]);
    }
    tau->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), skinFrictionUnits(options.viscosity).c_str());
    wall->GetCellData()->AddArray(tau);
    if (options.warn && unmatched > 0 && unmatched < size_t(wall->GetNumberOfCells()))
        options.warn(what + ": " + std::to_string(unmatched) + " of the " + std::to_string(wall->GetNumberOfCells()) +
                     " faces of " + wallName + " are a face of no volume cell; zero there");
    else if (options.warn && unmatched > 0)
        options.warn(what + ": no face of " + wallName + " is a face of a volume cell; zero there");
    return unmatched;
}

}  // namespace

void addSkinFriction(vtkDataSet* volume, const std::vector<vtkPolyData*>& walls,
                     const std::vector<std::string>& wallNames, const SkinFrictionOptions& options,
                     const std::string& where) {
    const std::string what = where + ": --field " + kSkinFrictionName;
    const WallArrays arrays = volumeVelocity(volume, options, what);
    const PointMatches matches = matchPoints(volume, walls);
    Scratch scratch;
    size_t matchedFaces = 0, totalFaces = 0;
    for (size_t w = 0; w < walls.size(); ++w) {
        vtkPolyData* wall = walls[w];
        auto ownerOf = [&](vtkIdType f, std::vector<const std::vector<vtkIdType>*>& faceMatches) {
            vtkIdType n;
            const vtkIdType* ids;
            wall->GetCellPoints(f, n, ids);
            for (vtkIdType k = 0; k < n; ++k) faceMatches.push_back(&matches.at(keyOf(wall->GetPoints(), ids[k])));
            return ownerCell(volume, faceMatches, scratch.cells, scratch.cellPoints);
        };
        const size_t unmatched = addWallStress(volume, wall, wallNames[w], arrays, options, what, ownerOf);
        totalFaces += size_t(wall->GetNumberOfCells());
        matchedFaces += size_t(wall->GetNumberOfCells()) - unmatched;
    }
    if (totalFaces > 0 && matchedFaces == 0)
        throw FormatError(what + ": none of the " + std::to_string(totalFaces) +
                          " wall faces is a face of a volume cell (the walls and the volume share no points)");
}

void addSkinFrictionOnCells(vtkDataSet* volume, vtkPolyData* wall, const std::vector<vtkIdType>& cells,
                            const std::vector<vtkIdType>& faceOffsets, const std::vector<vtkIdType>& facePoints,
                            const std::string& wallName, const SkinFrictionOptions& options, const std::string& where) {
    const std::string what = where + ": --field " + kSkinFrictionName;
    const WallArrays arrays = volumeVelocity(volume, options, what);
    if (cells.size() != size_t(wall->GetNumberOfCells()) || faceOffsets.size() != cells.size() + 1)
        throw FormatError(what + ": " + wallName + " has " + std::to_string(wall->GetNumberOfCells()) + " faces, " +
                          std::to_string(cells.size()) + " owner cells known");
    std::vector<std::vector<vtkIdType>> single;  // each face point as its one volume point
    auto ownerOf = [&](vtkIdType f, std::vector<const std::vector<vtkIdType>*>& faceMatches) {
        single.assign(size_t(faceOffsets[size_t(f) + 1] - faceOffsets[size_t(f)]), {});
        for (size_t k = 0; k < single.size(); ++k) {
            single[k] = {facePoints[size_t(faceOffsets[size_t(f)]) + k]};
            faceMatches.push_back(&single[k]);
        }
        return cells[size_t(f)];
    };
    const size_t unmatched = addWallStress(volume, wall, wallName, arrays, options, what, ownerOf);
    if (unmatched > 0 && unmatched == cells.size())
        throw FormatError(what + ": no face of " + wallName + " is a face of a volume cell of the zone");
}

void addZeroSkinFriction(vtkDataSet* surface, double viscosity) {
    auto zero = vtkSmartPointer<vtkDoubleArray>::New();
    zero->SetName(kSkinFrictionName);
    zero->SetNumberOfComponents(3);
    zero->SetNumberOfTuples(surface->GetNumberOfCells());
    zero->Fill(0.0);
    zero->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), skinFrictionUnits(viscosity).c_str());
    surface->GetCellData()->AddArray(zero);
}

// --- boundary surfaces of volume files --------------------------------------------------------
vtkSmartPointer<vtkPolyData> newBoundaryWithSkinFriction(vtkDataSet* volume, const SkinFrictionOptions& options,
                                                         const std::string& where) {
    auto filter = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
    filter->SetInputData(volume);
    filter->Update();
    auto boundary = vtkSmartPointer<vtkPolyData>::New();
    boundary->ShallowCopy(filter->GetOutput());
    // The filter copies the owner cell's data onto each face: a cell velocity there is the
    // cell's, not the wall's, and must not be taken for a moving wall.
    addSkinFriction(volume, {boundary.Get()}, {"the boundary surface"}, options, where);
    return boundary;
}

}  // namespace flowsurf::io::detail
