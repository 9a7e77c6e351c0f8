// Readers on small files written here (VTK writers, or text for OBJ/STL/PLY/OpenFOAM):
// counts after triangulation, field names and values, cell data → point data, time steps.
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"

#include "test_io_common.h"

#include <vtkCellType.h>
#include <vtkExodusIIWriter.h>
#include <vtkPolyDataWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

void writeVtp(vtkPolyData* data, const std::string& path) {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(data);
    w->SetFileName(path.c_str());
    ASSERT_EQ(w->Write(), 1);
}

// One unit cube hexahedron, point "U" = (x, y, z), cell "cellVec" = (0, 0, 7).
vtkSmartPointer<vtkUnstructuredGrid> makeHex() {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto u = makeArray("U", 3);
    const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    for (const auto& c : corners) {
        points->InsertNextPoint(c);
        u->InsertNextTuple(c);
    }
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    vtkIdType ids[8] = {0, 1, 2, 3, 4, 5, 6, 7};
    grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
    auto cellVec = makeArray("cellVec", 3);
    cellVec->InsertNextTuple3(0, 0, 7);
    grid->GetPointData()->AddArray(u);
    grid->GetCellData()->AddArray(cellVec);
    return grid;
}

const core::VectorField& field(const core::SurfaceMesh& mesh, const std::string& name) {
    const core::VectorField* f = mesh.findField(name);
    if (!f) throw std::runtime_error("no field " + name);
    return *f;
}

// Index of the vertex at `p` (the readers may reorder points).
size_t vertexAt(const core::SurfaceMesh& mesh, glm::vec3 p) {
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        if (glm::length(mesh.positions[i] - p) < 1e-6f) return i;
    throw std::runtime_error("no vertex there");
}

}  // namespace

TEST(IoReaders, VtpQuadsAreTriangulatedWithPointAndCellFields) {
    ScratchDir dir;
    writeVtp(makeGrid(2, 2), dir.file("grid.vtp"));
    core::Dataset ds = io::readDataset(dir.file("grid.vtp"));
    ASSERT_EQ(ds.steps.size(), 1u);
    const auto& mesh = ds.steps[0].mesh;
    EXPECT_EQ(mesh.vertexCount(), 9u);
    EXPECT_EQ(mesh.triangleCount(), 8u);  // 4 quads
    ASSERT_EQ(mesh.fields.size(), 2u);   // U and cellVec; scalars are not fields
    EXPECT_EQ(field(mesh, "U").values[vertexAt(mesh, {2, 1, 0})], glm::vec3(1, 1, 0));
    // cellVec = (cell, 0, 2): a corner sees one cell, the centre the average of four.
    const auto& cellVec = field(mesh, "cellVec").values;
    EXPECT_EQ(cellVec[vertexAt(mesh, {0, 0, 0})], glm::vec3(0, 0, 2));
    EXPECT_EQ(cellVec[vertexAt(mesh, {2, 2, 0})], glm::vec3(3, 0, 2));
    EXPECT_EQ(cellVec[vertexAt(mesh, {1, 1, 0})], glm::vec3(1.5f, 0, 2));
    ASSERT_EQ(mesh.normals.size(), 9u);  // computed: none in the file
    EXPECT_NEAR(std::abs(mesh.normals[4].z), 1.0f, 1e-6f);
}

TEST(IoReaders, PointArrayWinsOverCellArrayOfTheSameName) {
    ScratchDir dir;
    auto grid = makeGrid(1, 1);
    auto cellU = makeArray("U", 3);
    cellU->InsertNextTuple3(100, 100, 100);
    grid->GetCellData()->AddArray(cellU);
    writeVtp(grid, dir.file("clash.vtp"));
    const auto mesh = io::readDataset(dir.file("clash.vtp")).steps[0].mesh;
    EXPECT_EQ(field(mesh, "U").values[vertexAt(mesh, {1, 0, 0})], glm::vec3(1, 0.5f, 0));
    EXPECT_EQ(std::count_if(mesh.fields.begin(), mesh.fields.end(),
                            [](const core::VectorField& f) { return f.name == "U"; }),
              1);
}

TEST(IoReaders, FileNormalsAreUsedAndNotAField) {
    ScratchDir dir;
    auto grid = makeGrid(1, 1, true);
    auto normals = makeArray("Normals", 3);
    for (int i = 0; i < 4; ++i) normals->InsertNextTuple3(0, 0, -2);  // not unit: normalised
    grid->GetPointData()->AddArray(normals);
    writeVtp(grid, dir.file("normals.vtp"));
    const auto mesh = io::readDataset(dir.file("normals.vtp")).steps[0].mesh;
    ASSERT_EQ(mesh.normals.size(), 4u);
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, -1));
    EXPECT_EQ(mesh.findField("Normals"), nullptr);
}

TEST(IoReaders, AppendedAndCompressedVtpReadLikeAscii) {
    ScratchDir dir;
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(makeGrid(3, 2));
    w->SetFileName(dir.file("ascii.vtp").c_str());
    w->SetDataModeToAscii();
    ASSERT_EQ(w->Write(), 1);
    w->SetFileName(dir.file("raw.vtp").c_str());
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOff();
    w->SetCompressorTypeToNone();
    ASSERT_EQ(w->Write(), 1);
    w->SetFileName(dir.file("zlib.vtp").c_str());
    w->SetCompressorTypeToZLib();
    ASSERT_EQ(w->Write(), 1);
    for (const char* name : {"ascii.vtp", "raw.vtp", "zlib.vtp"}) {
        SCOPED_TRACE(name);
        const auto mesh = io::readDataset(dir.file(name)).steps[0].mesh;
        EXPECT_EQ(mesh.vertexCount(), 12u);
        EXPECT_EQ(mesh.triangleCount(), 12u);
        EXPECT_EQ(field(mesh, "U").values[vertexAt(mesh, {3, 2, 0})], glm::vec3(1, 1.5f, 0));
    }
}

TEST(IoReaders, VtuVolumeGivesItsBoundarySurface) {
    ScratchDir dir;
    auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    w->SetInputData(makeHex());
    w->SetFileName(dir.file("hex.VTU").c_str());  // extensions are case-insensitive
    ASSERT_EQ(w->Write(), 1);
    const auto mesh = io::readDataset(dir.file("hex.VTU")).steps[0].mesh;
    EXPECT_EQ(mesh.vertexCount(), 8u);
    EXPECT_EQ(mesh.triangleCount(), 12u);  // 6 quads
    EXPECT_EQ(field(mesh, "U").values[vertexAt(mesh, {1, 0, 1})], glm::vec3(1, 0, 1));
    EXPECT_EQ(field(mesh, "cellVec").values[vertexAt(mesh, {0, 1, 1})], glm::vec3(0, 0, 7));
}

TEST(IoReaders, LegacyVtkAsciiBinaryAndUnstructured) {
    ScratchDir dir;
    auto pw = vtkSmartPointer<vtkPolyDataWriter>::New();
    pw->SetInputData(makeGrid(2, 1));
    pw->SetFileName(dir.file("ascii.vtk").c_str());
    ASSERT_EQ(pw->Write(), 1);
    pw->SetFileName(dir.file("binary.vtk").c_str());
    pw->SetFileTypeToBinary();
    ASSERT_EQ(pw->Write(), 1);
    for (const char* name : {"ascii.vtk", "binary.vtk"}) {
        SCOPED_TRACE(name);
        const auto mesh = io::readDataset(dir.file(name)).steps[0].mesh;
        EXPECT_EQ(mesh.vertexCount(), 6u);
        EXPECT_EQ(mesh.triangleCount(), 4u);
        EXPECT_NE(mesh.findField("cellVec"), nullptr);
    }
    auto uw = vtkSmartPointer<vtkUnstructuredGridWriter>::New();
    uw->SetInputData(makeHex());
    uw->SetFileName(dir.file("hex.vtk").c_str());
    ASSERT_EQ(uw->Write(), 1);
    EXPECT_EQ(io::readDataset(dir.file("hex.vtk")).steps[0].mesh.triangleCount(), 12u);
    EXPECT_EQ(io::inspectFile(dir.file("hex.vtk")).format, "VTK legacy UnstructuredGrid");
}

TEST(IoReaders, ObjStlPlyGeometry) {
    ScratchDir dir;
    writeText(dir.file("quad.obj"), "# a quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                                    "f -4//1 -3//1 -2//1 -1//1\n");  // relative indices
    writeText(dir.file("quad.stl"),
              "solid t\n"
              "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 1 1 0\n"
              " endloop\nendfacet\n"
              "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 1 0\n  vertex 0 1 0\n"
              " endloop\nendfacet\nendsolid t\n");
    writeText(dir.file("quad.ply"),
              "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
              "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
    for (const char* name : {"quad.obj", "quad.stl", "quad.ply"}) {
        SCOPED_TRACE(name);
        const auto mesh = io::readDataset(dir.file(name)).steps[0].mesh;
        EXPECT_EQ(mesh.vertexCount(), 4u);  // STL: duplicate vertices merged
        EXPECT_EQ(mesh.triangleCount(), 2u);
        EXPECT_TRUE(mesh.fields.empty());
        EXPECT_EQ(mesh.normals.size(), 4u);
    }
}

TEST(IoReaders, PvdStepsSortedByTimeAndMaxSteps) {
    ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "sub");
    writeVtp(makeGrid(1, 1), dir.file("sub/a.vtp"));
    writeVtp(makeGrid(2, 1), dir.file("b.vtp"));
    writeText(dir.file("series.pvd"),
              "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
              "  <Collection>\n"
              "    <DataSet timestep=\"1.5\" part=\"0\" file=\"b.vtp\"/>\n"
              "    <DataSet timestep=\"0.5\" part=\"0\" file=\"sub/a.vtp\"/>\n"
              "  </Collection>\n</VTKFile>\n");
    core::Dataset ds = io::readDataset(dir.file("series.pvd"));
    ASSERT_EQ(ds.steps.size(), 2u);
    EXPECT_DOUBLE_EQ(ds.steps[0].time, 0.5);
    EXPECT_DOUBLE_EQ(ds.steps[1].time, 1.5);
    EXPECT_EQ(ds.steps[0].mesh.triangleCount(), 2u);
    EXPECT_EQ(ds.steps[1].mesh.triangleCount(), 4u);
    io::ReadOptions one;
    one.maxSteps = 1;
    EXPECT_EQ(io::readDataset(dir.file("series.pvd"), one).steps.size(), 1u);
    EXPECT_EQ(io::inspectFile(dir.file("series.pvd")).times, (std::vector<double>{0.5, 1.5}));
}

TEST(IoReaders, ExodusWrittenByVtk) {
    ScratchDir dir;
    auto w = vtkSmartPointer<vtkExodusIIWriter>::New();
    w->SetInputData(makeHex());
    w->SetFileName(dir.file("hex.e").c_str());
    w->WriteAllTimeStepsOff();
    ASSERT_EQ(w->Write(), 1);
    const auto mesh = io::readDataset(dir.file("hex.e")).steps[0].mesh;
    EXPECT_EQ(mesh.triangleCount(), 12u);
    ASSERT_NE(mesh.findField("U"), nullptr);
    EXPECT_EQ(field(mesh, "U").values[vertexAt(mesh, {1, 1, 0})], glm::vec3(1, 1, 0));
}

TEST(IoReaders, InspectFileListsPointAndCellArrays) {
    ScratchDir dir;
    writeVtp(makeGrid(2, 2), dir.file("grid.vtp"));
    io::FileInfo info = io::inspectFile(dir.file("grid.vtp"));
    EXPECT_EQ(info.format, "VTK XML PolyData");
    EXPECT_EQ(info.points, 9u);
    EXPECT_EQ(info.triangles, 8u);
    EXPECT_TRUE(info.times.empty());
    EXPECT_EQ(info.bounds.hi, glm::vec3(2, 2, 0));
    ASSERT_EQ(info.arrays.size(), 4u);
    auto find = [&](const std::string& name) {
        for (const auto& a : info.arrays)
            if (a.name == name) return a;
        throw std::runtime_error("no array " + name);
    };
    EXPECT_TRUE(find("U").pointData);
    EXPECT_EQ(find("U").components, 3);
    EXPECT_DOUBLE_EQ(find("U").rangeMax, std::sqrt(2.0));  // |(1, 1, 0)|
    EXPECT_FALSE(find("cellVec").pointData);
    EXPECT_DOUBLE_EQ(find("cellId").rangeMax, 3.0);
    const std::string text = io::formatFileInfo(info);
    EXPECT_NE(text.find("grid.vtp"), std::string::npos);
    EXPECT_NE(text.find("9 points, 8 triangles"), std::string::npos);
    EXPECT_NE(text.find("Vector fields U, cellVec"), std::string::npos);
}

namespace {

std::string foamFile(const char* cls, const char* object, const std::string& body) {
    return std::string("FoamFile\n{\n    version 2.0;\n    format ascii;\n    class ") + cls +
           ";\n    object " + object + ";\n}\n" + body;
}

// A one-cell OpenFOAM case: a unit cube with patches "bottom" (1 face) and "walls" (5),
// time directories 0 and 1 with U = (t, 0, 0) on bottom and (1, 2, t) on walls.
void writeCubeCase(const ScratchDir& dir) {
    for (const char* sub : {"system", "constant/polyMesh", "0", "1"})
        std::filesystem::create_directories(dir.path() / sub);
    writeText(dir.file("cube.foam"), "");
    writeText(dir.file("system/controlDict"),
              foamFile("dictionary", "controlDict",
                       "application icoFoam;\nstartTime 0;\nendTime 1;\ndeltaT 1;\n"));
    writeText(dir.file("constant/polyMesh/points"),
              foamFile("vectorField", "points",
                       "8\n(\n(0 0 0)\n(1 0 0)\n(1 1 0)\n(0 1 0)\n(0 0 1)\n(1 0 1)\n(1 1 1)\n(0 1 1)\n)\n"));
    writeText(dir.file("constant/polyMesh/faces"),
              foamFile("faceList", "faces",
                       "6\n(\n4(0 3 2 1)\n4(4 5 6 7)\n4(0 1 5 4)\n4(3 7 6 2)\n4(0 4 7 3)\n4(1 2 6 5)\n)\n"));
    writeText(dir.file("constant/polyMesh/owner"), foamFile("labelList", "owner", "6\n(\n0 0 0 0 0 0\n)\n"));
    writeText(dir.file("constant/polyMesh/neighbour"), foamFile("labelList", "neighbour", "0\n(\n)\n"));
    writeText(dir.file("constant/polyMesh/boundary"),
              foamFile("polyBoundaryMesh", "boundary",
                       "2\n(\nbottom\n{\ntype wall;\nnFaces 1;\nstartFace 0;\n}\n"
                       "walls\n{\ntype wall;\nnFaces 5;\nstartFace 1;\n}\n)\n"));
    for (const char* t : {"0", "1"})
        writeText(dir.file(std::string(t) + "/U"),
                  foamFile("volVectorField", "U",
                           std::string("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n"
                                       "boundaryField\n{\nbottom\n{\ntype fixedValue;\nvalue uniform (") +
                               t + " 0 0);\n}\nwalls\n{\ntype fixedValue;\nvalue uniform (1 2 " + t +
                               ");\n}\n}\n"));
}

}  // namespace

TEST(IoReaders, OpenFoamBoundaryPatchesAndTimeDirectories) {
    ScratchDir dir;
    writeCubeCase(dir);
    core::Dataset ds = io::readDataset(dir.file("cube.foam"));
    // The initial conditions in 0/ are skipped by default (a solved time exists), read
    // when asked for (--foam-zero-time).
    ASSERT_EQ(ds.steps.size(), 1u);
    EXPECT_DOUBLE_EQ(ds.steps[0].time, 1.0);
    auto withZero = io::openSeries(dir.file("cube.foam"), {.patches = {}, .foamCase = "auto", .zeroTime = true});
    ASSERT_EQ(withZero->count(), 2u);
    EXPECT_DOUBLE_EQ(withZero->time(0), 0.0);
    EXPECT_DOUBLE_EQ(withZero->time(1), 1.0);
    ds.steps.insert(ds.steps.begin(), core::TimeStep{0.0, withZero->load(0)});
    for (const auto& step : ds.steps) {
        // Two patch blocks, merged: 4 + 8 points, 6 quads. No internal mesh.
        EXPECT_EQ(step.mesh.vertexCount(), 12u);
        EXPECT_EQ(step.mesh.triangleCount(), 12u);
        ASSERT_NE(step.mesh.findField("U"), nullptr);
    }
    // Patch values reach the points: at t = 1 every point is (1, 0, 0) or (1, 2, 1).
    for (const auto& u : field(ds.steps[1].mesh, "U").values)
        EXPECT_TRUE(u == glm::vec3(1, 0, 0) || u == glm::vec3(1, 2, 1)) << u.x << " " << u.y << " " << u.z;
    // A broken mesh file is a FormatError naming the case.
    writeText(dir.file("constant/polyMesh/faces"), foamFile("faceList", "faces", "6\n(\n4(0 3 2 1)\n"));
    EXPECT_THROW(io::readDataset(dir.file("cube.foam")), FormatError);
}

TEST(IoReaders, EnSightGoldAsciiWithTimeSteps) {
    ScratchDir dir;
    writeText(dir.file("t.case"),
              "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: mesh.geo\n\nVARIABLE\n"
              "vector per node: U U.****\n\nTIME\ntime set: 1\nnumber of steps: 2\n"
              "filename start number: 0\nfilename increment: 1\ntime values: 0.0 0.5\n");
    auto column = [](std::initializer_list<double> values) {
        std::string s;
        for (double v : values) s.append(" ").append(std::to_string(v)).append("\n");
        return s;
    };
    writeText(dir.file("mesh.geo"),
              "EnSight test\ngeometry\nnode id off\nelement id off\npart\n         1\nquad\n"
              "coordinates\n         4\n" + column({0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0}) +
              "quad4\n         1\n         1         2         3         4\n");
    for (int t : {0, 1})
        writeText(dir.file("U.000" + std::to_string(t)),
                  "vector per node\npart\n         1\ncoordinates\n" +
                      column({1, 1, 1, 1, double(t), double(t), double(t), double(t), 0, 0, 0, 0}));
    core::Dataset ds = io::readDataset(dir.file("t.case"));
    ASSERT_EQ(ds.steps.size(), 2u);
    EXPECT_DOUBLE_EQ(ds.steps[1].time, 0.5);
    EXPECT_EQ(ds.steps[1].mesh.triangleCount(), 2u);
    EXPECT_EQ(field(ds.steps[1].mesh, "U").values[2], glm::vec3(1, 1, 0));
}
