// --field skin-friction: the wall shear stress derived from the velocity next to the walls,
// read through the reader process as a user reads it. Plane Couette flow u(y) = u0 + s·y
// between two moving walls, where the one-cell difference is exact: τ = ν·s along the flow
// on the lower wall, −ν·s on the upper one, whatever the walls' own speed. Written as a
// generated ASCII OpenFOAM case (hexahedra with internal faces, walls that move, a velocity
// component through the walls that is not tangential) and as a .vtu volume with point
// velocities; and the errors a user meets.
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader/surface_pipeline.h"
#include "io/reader/vtk_sources.h"
#include "io/series_reader.h"
#include "test_io_common.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataSet.h>
#include <vtkDoubleArray.h>
#include <vtkGenericCell.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

// The flow: u = (u0 + s·y, c, t·y); walls at y = 0 and y = H move with the flow there.
constexpr double kU0 = 3.0, kS = 2.0, kC = 0.7, kT = -0.5;
constexpr double kL = 2.0, kH = 1.0, kDz = 0.5;
constexpr int kNx = 4, kNy = 5;

glm::dvec3 flowAt(double y) { return {kU0 + kS * y, kC, kT * y}; }
glm::dvec3 wallVelocity(double y) { return {kU0 + kS * y, 0.0, kT * y}; }  // no flow through the wall

std::string header(const std::string& cls, const std::string& object) {
    return "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class " + cls + ";\n    object " + object + ";\n}\n";
}

std::string vec(const glm::dvec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << v.x << " " << v.y << " " << v.z << ")";
    return s.str();
}

// Columns [i0, i0 + n) of a kNx × kNy × 1 block of hexahedra in OpenFOAM's layout below
// `dir`: internal faces first (upper triangular: by owner, then neighbour), then the patches
// lower (y = 0) and upper (y = H), walls, sides (the domain's x ends and the z faces), and
// where the columns end inside the domain a processor patch (decomposePar's layout); each
// face's normal out of its owner cell. U holds the flow at the cell centres and the walls'
// velocity as their patch values.
void writeCouetteBlock(const fs::path& dir, int i0, int n) {
    const fs::path mesh = dir / "constant/polyMesh";
    fs::create_directories(mesh);
    fs::create_directories(dir / "1");
    auto p = [i0, n](int i, int j, int k) { return (i - i0) + (n + 1) * (j + (kNy + 1) * k); };
    auto cell = [i0, n](int i, int j) { return (i - i0) + n * j; };
    std::string points = std::to_string((n + 1) * (kNy + 1) * 2) + "\n(\n";
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j <= kNy; ++j)
            for (int i = i0; i <= i0 + n; ++i) points += vec({kL * i / kNx, kH * j / kNy, kDz * k}) + "\n";
    std::vector<std::string> faces;
    std::vector<int> owner, neighbour;
    auto quad = [&](int a, int b, int c, int d, int own) {
        faces.push_back("4(" + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " " +
                        std::to_string(d) + ")");
        owner.push_back(own);
    };
    auto xFace = [&](int x, int j, int own) { quad(p(x, j, 0), p(x, j + 1, 0), p(x, j + 1, 1), p(x, j, 1), own); };
    auto xFaceBack = [&](int x, int j, int own) { quad(p(x, j, 0), p(x, j, 1), p(x, j + 1, 1), p(x, j + 1, 0), own); };
    auto yFace = [&](int i, int y, int own) { quad(p(i, y, 0), p(i, y, 1), p(i + 1, y, 1), p(i + 1, y, 0), own); };
    for (int j = 0; j < kNy; ++j)
        for (int i = i0; i < i0 + n; ++i) {
            if (i + 1 < i0 + n) xFace(i + 1, j, cell(i, j)), neighbour.push_back(cell(i + 1, j));
            if (j + 1 < kNy) yFace(i, j + 1, cell(i, j)), neighbour.push_back(cell(i, j + 1));
        }
    const size_t internal = faces.size();
    for (int i = i0; i < i0 + n; ++i) quad(p(i, 0, 0), p(i + 1, 0, 0), p(i + 1, 0, 1), p(i, 0, 1), cell(i, 0));
    for (int i = i0; i < i0 + n; ++i) yFace(i, kNy, cell(i, kNy - 1));
    const size_t sides = faces.size();
    for (int j = 0; j < kNy; ++j) {
        if (i0 == 0) xFaceBack(0, j, cell(0, j));
        if (i0 + n == kNx) xFace(kNx, j, cell(kNx - 1, j));
        for (int i = i0; i < i0 + n; ++i) {
            quad(p(i, j, 0), p(i, j + 1, 0), p(i + 1, j + 1, 0), p(i + 1, j, 0), cell(i, j));
            quad(p(i, j, 1), p(i + 1, j, 1), p(i + 1, j + 1, 1), p(i, j + 1, 1), cell(i, j));
        }
    }
    const size_t processor = faces.size();
    for (int j = 0; j < kNy; ++j) {
        if (i0 > 0) xFaceBack(i0, j, cell(i0, j));
        if (i0 + n < kNx) xFace(i0 + n, j, cell(i0 + n - 1, j));
    }
    auto list = [](const auto& items) {
        std::string s = std::to_string(items.size()) + "\n(\n";
        for (const auto& x : items) {
            std::ostringstream o;
            o << x << "\n";
            s += o.str();
        }
        return s + ")\n";
    };
    writeText((mesh / "points").string(), header("vectorField", "points") + points + ")\n");
    writeText((mesh / "faces").string(), header("faceList", "faces") + list(faces));
    writeText((mesh / "owner").string(), header("labelList", "owner") + list(owner));
    writeText((mesh / "neighbour").string(), header("labelList", "neighbour") + list(neighbour));
    auto patch = [](const std::string& name, const std::string& type, size_t count, size_t start,
                    const std::string& extra = "") {
        return name + "\n{\n type " + type + ";\n nFaces " + std::to_string(count) + ";\n startFace " +
               std::to_string(start) + ";\n" + extra + "}\n";
    };
    const bool decomposed = processor < faces.size();
    const int me = i0 == 0 ? 0 : 1;
    const std::string proc = "procBoundary" + std::to_string(me) + "to" + std::to_string(1 - me);
    std::string boundary = patch("lower", "wall", size_t(n), internal) + patch("upper", "wall", size_t(n), internal + n) +
                           patch("sides", "patch", processor - sides, sides);
    if (decomposed)
        boundary += patch(proc, "processor", faces.size() - processor, processor,
                          " inGroups 1(processor);\n matchTolerance 0.0001;\n transform unknown;\n myProcNo " +
                              std::to_string(me) + ";\n neighbProcNo " + std::to_string(1 - me) + ";\n");
    writeText((mesh / "boundary").string(), header("polyBoundaryMesh", "boundary") + (decomposed ? "4" : "3") +
                                                "\n(\n" + boundary + ")\n");
    std::string cells = std::to_string(n * kNy) + "\n(\n";
    for (int j = 0; j < kNy; ++j)
        for (int i = i0; i < i0 + n; ++i) cells += vec(flowAt(kH * (j + 0.5) / kNy)) + "\n";
    writeText((dir / "1/U").string(),
              header("volVectorField", "U") + "dimensions [0 1 -1 0 0 0 0];\ninternalField nonuniform List<vector>\n" +
                  cells + ")\n;\nboundaryField\n{\n lower\n {\n type movingWallVelocity;\n value uniform " +
                  vec(wallVelocity(0)) + ";\n }\n upper\n {\n type movingWallVelocity;\n value uniform " +
                  vec(wallVelocity(kH)) + ";\n }\n sides\n {\n type zeroGradient;\n value uniform (0 0 0);\n }\n" +
                  (decomposed ? " " + proc + "\n {\n type processor;\n value uniform (0 0 0);\n }\n" : "") + "}\n");
}

// The whole block as a reconstructed case, or (`decomposed`) split in two processor
// directories with nothing in the case folder but constant/transportProperties and system/.
void writeCouetteCase(const fs::path& dir, const std::string& transport, bool decomposed = false) {
    if (decomposed) {
        writeCouetteBlock(dir / "processor0", 0, kNx / 2);
        writeCouetteBlock(dir / "processor1", kNx / 2, kNx - kNx / 2);
    } else {
        writeCouetteBlock(dir, 0, kNx);
    }
    fs::create_directories(dir / "constant");
    fs::create_directories(dir / "system");
    if (!transport.empty())
        writeText((dir / "constant/transportProperties").string(), header("dictionary", "transportProperties") + transport);
    writeText((dir / "system/controlDict").string(),
              header("dictionary", "controlDict") + "application simpleFoam;\nstartTime 0;\nendTime 1;\ndeltaT 1;\n");
    writeText((dir / "case.foam").string(), "");
}

// Every point of the surface on a wall (y = 0 or H) must carry ±ν·(s, 0, t).
void expectCouetteStress(const core::SurfaceMesh& m, double nu, const std::string& what) {
    SCOPED_TRACE(what);
    const core::VectorField* tau = m.findField("skin-friction");
    ASSERT_NE(tau, nullptr);
    size_t lower = 0, upper = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const float y = m.positions[i].y;
        const bool onLower = std::abs(y) < 1e-6f, onUpper = std::abs(y - float(kH)) < 1e-6f;
        const bool onSide = m.positions[i].x < 1e-6f || m.positions[i].x > float(kL) - 1e-6f ||
                            m.positions[i].z < 1e-6f || m.positions[i].z > float(kDz) - 1e-6f;
        if (!onLower && !onUpper) continue;
        if (onSide && (tau->values[i] == glm::vec3(0.0f))) continue;  // a side patch's copy of an edge point
        const float sign = onLower ? 1.0f : -1.0f;
        (onLower ? lower : upper)++;
        EXPECT_NEAR(tau->values[i].x, sign * nu * kS, 1e-4 * nu * kS) << "point " << i << " y " << y;
        EXPECT_NEAR(tau->values[i].y, 0.0, 1e-4 * nu * kS) << "point " << i;
        EXPECT_NEAR(tau->values[i].z, sign * nu * kT, 1e-4 * nu * kS) << "point " << i;
    }
    EXPECT_GT(lower, 0u);
    EXPECT_GT(upper, 0u);
}

core::SurfaceMesh readSkinFriction(const std::string& path, double viscosity = 0) {
    io::SourceOptions o;
    o.skinFriction = true;
    o.viscosity = viscosity;
    return io::openSeries(path, o)->load(0);
}

}  // namespace

TEST(SkinFriction, CouetteFlowOpenFoamCaseGivesNuTimesShearAlongTheFlowOnMovingWalls) {
    ScratchDir dir;
    writeCouetteCase(dir.path(), "transportModel Newtonian;\nnu [0 2 -1 0 0 0 0] 0.002;\n");
    const core::SurfaceMesh m = readSkinFriction(dir.file("case.foam"));
    expectCouetteStress(m, 0.002, "nu from constant/transportProperties");
    EXPECT_EQ(m.units.at("skin-friction"), "m2/s2");
    // The side patches are no walls: no stress there, as OpenFOAM's function object writes.
    const core::VectorField* tau = m.findField("skin-friction");
    for (size_t i = 0; i < m.positions.size(); ++i)
        if (m.positions[i].y > 0.3f && m.positions[i].y < 0.7f) {
            EXPECT_EQ(tau->values[i], glm::vec3(0.0f)) << i;
        }
    // The stored velocity is still there, as stored.
    EXPECT_NE(m.findField("U"), nullptr);
}

// decomposePar's layout: the wall faces of each processor's piece find their cells in that
// piece (the appended pieces hold a copy of the points on the processor boundary each).
TEST(SkinFriction, DecomposedCaseGivesTheSameStress) {
    ScratchDir dir;
    writeCouetteCase(dir.path(), "nu 0.002;\n", true);
    const core::SurfaceMesh m = readSkinFriction(dir.file("case.foam"));
    expectCouetteStress(m, 0.002, "decomposed in two");
    size_t onWalls = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) onWalls += m.positions[i].y < 1e-6f;
    EXPECT_GE(onWalls, size_t(2 * (kNx + 2)));  // both pieces' lower wall (with the copies at x = L/2)
    const std::string note = io::inspectFile(dir.file("case.foam")).skinFriction;
    EXPECT_EQ(note.rfind("from U", 0), 0u) << note;
}

TEST(SkinFriction, ViscosityOptionWinsAndWithoutAnyTheMagnitudeIsTheRelativeGradient) {
    ScratchDir dir;
    writeCouetteCase(dir.path(), "nu 0.002;\n");
    expectCouetteStress(readSkinFriction(dir.file("case.foam"), 0.5), 0.5, "--viscosity 0.5");
    ScratchDir bare;
    writeCouetteCase(bare.path(), "");
    const core::SurfaceMesh m = readSkinFriction(bare.file("case.foam"));
    expectCouetteStress(m, 1.0, "no viscosity: du/dy");
    EXPECT_NE(m.units.at("skin-friction").find("relative"), std::string::npos) << m.units.at("skin-friction");
}

TEST(SkinFriction, WithoutTheOptionTheCaseReadsAsBefore) {
    ScratchDir dir;
    writeCouetteCase(dir.path(), "nu 0.002;\n");
    const core::SurfaceMesh m = io::openSeries(dir.file("case.foam"))->load(0);
    EXPECT_EQ(m.findField("skin-friction"), nullptr);
    EXPECT_NE(m.findField("U"), nullptr);
}

TEST(SkinFriction, InfoSaysWhereItComesFrom) {
    ScratchDir dir;
    writeCouetteCase(dir.path(), "nu 0.002;\n");
    const io::FileInfo info = io::inspectFile(dir.file("case.foam"));
    EXPECT_NE(info.skinFriction.find("lower, upper"), std::string::npos) << info.skinFriction;
    EXPECT_NE(info.skinFriction.find("0.002"), std::string::npos) << info.skinFriction;
    fs::remove(dir.path() / "1/U");
    writeText(dir.file("1/p"), header("volScalarField", "p") +
                                   "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\nboundaryField\n{\n \".*\"\n {\n "
                                   "type zeroGradient;\n }\n}\n");
    EXPECT_EQ(io::inspectFile(dir.file("case.foam")).skinFriction.rfind("not available", 0), 0u);
}

TEST(SkinFriction, MissingVelocityOrNoVolumeIsAnErrorNamingTheFile) {
    ScratchDir dir;
    writeCouetteCase(dir.path(), "nu 0.002;\n");
    fs::remove(dir.path() / "1/U");
    writeText(dir.file("1/p"), header("volScalarField", "p") +
                                   "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\nboundaryField\n{\n \".*\"\n {\n "
                                   "type zeroGradient;\n }\n}\n");
    try {
        readSkinFriction(dir.file("case.foam"));
        ADD_FAILURE() << "no exception";
    } catch (const FieldError& e) {
        EXPECT_NE(std::string(e.what()).find("case.foam"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("velocity field U"), std::string::npos) << e.what();
    }
    // A surface file has no volume to take the gradient in.
    const std::string vtp = dir.file("plane.vtp");
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(makeGrid(3, 3));
    writer->SetFileName(vtp.c_str());
    writer->Write();
    try {
        readSkinFriction(vtp);
        ADD_FAILURE() << "no exception";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("plane.vtp"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("surface only"), std::string::npos) << e.what();
    }
}

namespace {

// The same flow in a .vtu of hexahedra with the velocity at the points (walls included: there
// the points carry the walls' velocity).
std::string writeCouetteVtu(const ScratchDir& dir, bool withVelocity) {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto u = vtkSmartPointer<vtkDoubleArray>::New();
    u->SetName("velocity");
    u->SetNumberOfComponents(3);
    auto p = [](int i, int j, int k) { return vtkIdType(i + (kNx + 1) * (j + (kNy + 1) * k)); };
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j <= kNy; ++j)
            for (int i = 0; i <= kNx; ++i) {
                const double y = kH * j / kNy;
                points->InsertNextPoint(kL * i / kNx, y, kDz * k);
                const glm::dvec3 v = (j == 0 || j == kNy) ? wallVelocity(y) : flowAt(y);
                u->InsertNextTuple3(v.x, v.y, v.z);
            }
    grid->SetPoints(points);
    for (int j = 0; j < kNy; ++j)
        for (int i = 0; i < kNx; ++i) {
            const vtkIdType ids[8] = {p(i, j, 0), p(i + 1, j, 0), p(i + 1, j + 1, 0), p(i, j + 1, 0),
                                      p(i, j, 1), p(i + 1, j, 1), p(i + 1, j + 1, 1), p(i, j + 1, 1)};
            grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
        }
    if (withVelocity) grid->GetPointData()->AddArray(u);
    const std::string path = dir.file(withVelocity ? "couette.vtu" : "novelocity.vtu");
    auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    w->SetInputData(grid);
    w->SetFileName(path.c_str());
    w->Write();
    return path;
}

}  // namespace

// Point velocities: the cell's mean (at its centre, for a linear profile) against the wall
// face's points; v jumps from 0 on the wall to c inside, normal to the wall, which the
// tangential part leaves out. Checked per face (the boundary surface shares its points
// between the walls and the x and z faces, whose stress is zero, so point values mix them).
TEST(SkinFriction, VtuVolumeBoundaryIsTheWallWithPointVelocities) {
    ScratchDir dir;
    const std::string path = writeCouetteVtu(dir, true);
    io::detail::VtkMessageTrap trap;
    io::SourceOptions o;
    o.skinFriction = true;
    o.viscosity = 0.01;
    vtkSmartPointer<vtkDataObject> step = io::detail::openSource(path, trap, o)->readStep(0);
    auto* boundary = vtkPolyData::SafeDownCast(step);
    ASSERT_NE(boundary, nullptr);
    vtkDataArray* tau = boundary->GetCellData()->GetArray("skin-friction");
    ASSERT_NE(tau, nullptr);
    size_t walls = 0, others = 0;
    for (vtkIdType f = 0; f < boundary->GetNumberOfCells(); ++f) {
        double lo[6];
        boundary->GetCell(f)->GetBounds(lo);
        double t[3];
        tau->GetTuple(f, t);
        const bool lower = lo[3] < 1e-9, upper = lo[2] > kH - 1e-9;  // y max at 0, y min at H
        if (lower || upper) {
            const double sign = lower ? 1.0 : -1.0;
            // Within the float precision of the file's points.
            EXPECT_NEAR(t[0], sign * 0.01 * kS, 1e-7) << f;
            EXPECT_NEAR(t[1], 0.0, 1e-7) << f;
            EXPECT_NEAR(t[2], sign * 0.01 * kT, 1e-7) << f;
            ++walls;
        } else {
            // x and z faces: the velocity does not change across them.
            EXPECT_NEAR(std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]), 0.0, 1e-7) << f;
            ++others;
        }
    }
    EXPECT_EQ(walls, size_t(2 * kNx));
    EXPECT_EQ(others, size_t(2 * kNy + 2 * kNx * kNy));
    // Through the reader process, as a user reads it: the field and its units.
    const core::SurfaceMesh m = readSkinFriction(path, 0.01);
    ASSERT_NE(m.findField("skin-friction"), nullptr);
    EXPECT_EQ(m.units.at("skin-friction"), "m2/s2");
}

TEST(SkinFriction, VtuWithoutVelocityIsAFieldErrorListingItsArrays) {
    ScratchDir dir;
    const std::string path = writeCouetteVtu(dir, false);
    try {
        readSkinFriction(path);
        ADD_FAILURE() << "no exception";
    } catch (const FieldError& e) {
        EXPECT_NE(std::string(e.what()).find("novelocity.vtu"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no velocity"), std::string::npos) << e.what();
    }
}

// --- against the solver ---------------------------------------------------------------------
// OpenFOAM's wallShearStress (function object, the stress on the fluid) negated, face by face
// on the wall patches: the angle to skin-friction and the ratio of magnitudes. OpenFOAM's value
// is the whole traction −n·R_eff, with a normal part where the velocity gradient at the wall
// has one (corners, curved or skewed walls): compared as written and with its tangential part.
namespace {

struct Agreement {
    size_t faces = 0;
    double medianAngleDeg = 0, within10 = 0;           // against the tangential part
    double medianAngleRawDeg = 0, within10Raw = 0;     // against the vector as written
    double medianRatio = 0, ratio10 = 0, ratio90 = 0;  // |skin-friction| / |tangential part|
};

double quantile(std::vector<double> v, double q) {
    const size_t k = size_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

double shareWithin(const std::vector<double>& angles, double deg) {
    return double(std::count_if(angles.begin(), angles.end(), [deg](double a) { return a <= deg; })) / double(angles.size());
}

Agreement compareWithSolver(const std::string& path) {
    io::detail::VtkMessageTrap trap;
    io::SourceOptions o;
    o.skinFriction = true;
    auto source = io::detail::openSource(path, trap, o);
    vtkSmartPointer<vtkDataObject> step = source->readStep(source->stepCount() - 1);
    std::vector<double> angles, rawAngles, ratios;
    auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
        const double la = glm::length(a), lb = glm::length(b);
        const double c = la > 0 && lb > 0 ? glm::dot(a, b) / (la * lb) : -1.0;
        return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
    };
    io::detail::forEachNamedLeaf(step, [&](vtkDataSet* ds, const std::string&) {
        auto* patch = vtkPolyData::SafeDownCast(ds);
        vtkDataArray* sf = ds->GetCellData()->GetArray("skin-friction");
        vtkDataArray* wss = ds->GetCellData()->GetArray("wallShearStress");
        if (!patch || !sf || !wss) return;
        for (vtkIdType f = 0; f < ds->GetNumberOfCells(); ++f) {
            glm::dvec3 a, b, n(0.0);
            sf->GetTuple(f, &a.x);
            wss->GetTuple(f, &b.x);
            if (glm::length(a) == 0 && glm::length(b) == 0) continue;  // no wall (a patch of another type)
            vtkIdType count;
            const vtkIdType* ids;
            patch->GetCellPoints(f, count, ids);
            for (vtkIdType k = 0; k < count; ++k) {  // Newell's normal
                glm::dvec3 p, q;
                patch->GetPoint(ids[k], &p.x);
                patch->GetPoint(ids[(k + 1) % count], &q.x);
                n += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
            }
            n = glm::normalize(n);
            const glm::dvec3 tangential = -(b - glm::dot(b, n) * n);
            angles.push_back(angle(a, tangential));
            rawAngles.push_back(angle(a, -b));
            ratios.push_back(glm::length(tangential) > 0 ? glm::length(a) / glm::length(tangential) : 1e30);
        }
    });
    Agreement r;
    r.faces = angles.size();
    if (angles.empty()) return r;
    r.medianAngleDeg = quantile(angles, 0.5);
    r.within10 = shareWithin(angles, 10.0);
    r.medianAngleRawDeg = quantile(rawAngles, 0.5);
    r.within10Raw = shareWithin(rawAngles, 10.0);
    r.medianRatio = quantile(ratios, 0.5);
    r.ratio10 = quantile(ratios, 0.1);
    r.ratio90 = quantile(ratios, 0.9);
    return r;
}

void printAgreement(const std::string& what, const Agreement& a) {
    std::printf("%s: %zu wall faces; against -wallShearStress's tangential part: median angle %.2f deg, %.1f %% within "
                "10 deg; as written: median %.2f deg, %.1f %% within 10 deg; |skin-friction|/|tangential part| median "
                "%.3f (10 %%: %.3f, 90 %%: %.3f)\n",
                what.c_str(), a.faces, a.medianAngleDeg, 100.0 * a.within10, a.medianAngleRawDeg, 100.0 * a.within10Raw,
                a.medianRatio, a.ratio10, a.ratio90);
}

}  // namespace

// A solved case given by FLOWSURF_SOLVED_FOAM_CASE (CASE/case.foam whose last time holds U
// and OpenFOAM's wallShearStress), e.g. windAroundBuildings from
// data/tools/run_openfoam_cases.sh; skipped without one (CI has no OpenFOAM).
TEST(SkinFriction, AgreesInDirectionWithTheSolversOwnStressOnAGivenCase) {
    const char* path = std::getenv("FLOWSURF_SOLVED_FOAM_CASE");
    if (!path || !*path) GTEST_SKIP() << "FLOWSURF_SOLVED_FOAM_CASE not set";
    const Agreement a = compareWithSolver(path);
    printAgreement(path, a);
    ASSERT_GT(a.faces, 0u);
    EXPECT_LT(a.medianAngleDeg, 5.0);
    EXPECT_GT(a.within10, 0.8);
}

// The shipped laminar cavity (tests/unit/data/openfoam_cavity_laminar/README.md): the lid
// moves, the corners are singular; the solver's stress is the same one-cell difference
// (snGrad) on its orthogonal mesh, so direction and magnitude agree closely.
TEST(SkinFriction, AgreesWithOpenFoamsWallShearStressOnALaminarLidDrivenCavity) {
    const std::string path = std::string(FLOWSURF_TEST_DATA) + "/openfoam_cavity_laminar/case.foam";
    const Agreement a = compareWithSolver(path);
    printAgreement("laminar cavity", a);
    EXPECT_EQ(a.faces, 80u);  // movingWall 20 + fixedWalls 60; frontAndBack (empty) is no wall
    EXPECT_LT(a.medianAngleDeg, 1.0);
    EXPECT_GT(a.within10, 0.95);
    EXPECT_NEAR(a.medianRatio, 1.0, 0.02);
}

// A cell flattened onto its wall face (its centre on the face's plane) has no wall distance
// to divide by: refused with the file and the face named, not a division by zero.
TEST(SkinFriction, ZeroWallDistanceIsAnErrorNamingTheFace) {
    ScratchDir dir;
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto u = vtkSmartPointer<vtkDoubleArray>::New();
    u->SetName("U");
    u->SetNumberOfComponents(3);
    for (int k = 0; k < 2; ++k)  // the top four points on the bottom four
        for (auto [x, z] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
            points->InsertNextPoint(x, 0.0, z);
            u->InsertNextTuple3(1.0, 0.0, 0.0);
        }
    grid->SetPoints(points);
    const vtkIdType ids[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
    grid->GetPointData()->AddArray(u);
    const std::string path = dir.file("flat.vtu");
    auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    w->SetInputData(grid);
    w->SetFileName(path.c_str());
    w->Write();
    try {
        readSkinFriction(path);
        ADD_FAILURE() << "no exception";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("flat.vtu"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("zero distance"), std::string::npos) << e.what();
    }
}
