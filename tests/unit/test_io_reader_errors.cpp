// Bad input to the readers: each case throws the right type, names the file, and
// prints nothing (VTK's own reports are captured, not shown).
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/reader/parsers.h"

#include "test_io_common.h"

#include <vtkAppendFilter.h>
#include <vtkCellArray.h>
#include <vtkExodusIIWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

void writeVtp(vtkPolyData* data, const std::string& path, int mode = vtkXMLWriter::Ascii,
              bool zlib = false) {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(data);
    w->SetFileName(path.c_str());
    w->SetDataMode(mode);
    w->EncodeAppendedDataOff();
    if (zlib) w->SetCompressorTypeToZLib();
    else w->SetCompressorTypeToNone();
    ASSERT_EQ(w->Write(), 1);
}

// A hand-written ASCII .vtp: three points, one triangle, with the given U values.
std::string tinyVtp(const std::string& uValues, const std::string& connectivity = "0 1 2") {
    return "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">\n"
           "<PointData><DataArray type=\"Float32\" Name=\"U\" NumberOfComponents=\"3\" "
           "format=\"ascii\">" + uValues + "</DataArray></PointData>\n"
           "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">"
           "0 0 0 1 0 0 0 1 0</DataArray></Points>\n"
           "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">" +
           connectivity + "</DataArray>\n"
           "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys>\n"
           "</Piece></PolyData></VTKFile>\n";
}

}  // namespace

TEST(IoReaders, MissingFileIsIoError) {
    ScratchDir dir;
    expectReadError<IoError>(dir.file("nope.vtp"), "nope.vtp: cannot open (No such file or directory)");
    EXPECT_THROW(io::inspectFile(dir.file("nope.vtp")), IoError);
    expectReadError<IoError>(dir.path().string(), dir.path().string(), "Is a directory");
}

TEST(IoReaders, UnknownExtensionIsFormatErrorListingSupported) {
    ScratchDir dir;
    writeText(dir.file("mesh.xyz"), "1 2 3\n");
    expectReadError<FormatError>(dir.file("mesh.xyz"), "mesh.xyz", ".vtp .vtu .vtk");
}

TEST(IoReaders, EmptyFileIsFormatError) {
    ScratchDir dir;
    for (const char* name : {"e.vtp", "e.vtu", "e.vtk", "e.obj", "e.stl", "e.ply", "e.e", "e.case", "e.pvd"}) {
        writeText(dir.file(name), "");
        expectReadError<FormatError>(dir.file(name), name, "empty");
    }
}

TEST(IoReaders, TruncatedVtpIsFormatErrorInEveryEncoding) {
    ScratchDir dir;
    struct Mode {
        const char* name;
        int mode;
        bool zlib;
    };
    const Mode modes[] = {{"ascii.vtp", vtkXMLWriter::Ascii, false},
                          {"base64.vtp", vtkXMLWriter::Binary, false},
                          {"raw.vtp", vtkXMLWriter::Appended, false},
                          {"zlib.vtp", vtkXMLWriter::Appended, true}};
    for (const auto& m : modes) {
        writeVtp(makeGrid(12, 10), dir.file(m.name), m.mode, m.zlib);
        const std::string bytes = readBytes(dir.file(m.name));
        // Cut points across header, arrays and (for appended) the raw block; not the
        // closing tags, after which the data is complete.
        for (int percent = 5; percent <= 90; percent += 5) {
            const std::string cut = "cut" + std::to_string(percent) + "_" + m.name;
            writeText(dir.file(cut), bytes.substr(0, bytes.size() * percent / 100));
            expectReadError<FormatError>(dir.file(cut), cut);
        }
    }
}

TEST(IoReaders, TruncatedLegacyStlPlyAreFormatErrors) {
    ScratchDir dir;
    auto grid = makeGrid(12, 10, true);
    auto legacy = vtkSmartPointer<vtkPolyDataWriter>::New();
    legacy->SetInputData(grid);
    legacy->SetFileName(dir.file("ascii.vtk").c_str());
    ASSERT_EQ(legacy->Write(), 1);
    legacy->SetFileName(dir.file("binary.vtk").c_str());
    legacy->SetFileTypeToBinary();
    ASSERT_EQ(legacy->Write(), 1);
    auto stl = vtkSmartPointer<vtkSTLWriter>::New();
    stl->SetInputData(grid);
    stl->SetFileName(dir.file("binary.stl").c_str());
    stl->SetFileTypeToBinary();
    ASSERT_EQ(stl->Write(), 1);
    auto ply = vtkSmartPointer<vtkPLYWriter>::New();
    ply->SetInputData(grid);
    ply->SetFileName(dir.file("ascii.ply").c_str());
    ply->SetFileTypeToASCII();
    ASSERT_EQ(ply->Write(), 1);
    ply->SetFileName(dir.file("binary.ply").c_str());
    ply->SetFileTypeToBinary();
    ASSERT_EQ(ply->Write(), 1);
    // Version 4.2: the old "count id id ..." cell lists, which VTK walks unchecked.
    legacy->SetFileVersion(vtkDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    legacy->SetFileName(dir.file("old-binary.vtk").c_str());
    ASSERT_EQ(legacy->Write(), 1);
    legacy->SetFileTypeToASCII();
    legacy->SetFileName(dir.file("old-ascii.vtk").c_str());
    ASSERT_EQ(legacy->Write(), 1);
    for (const char* name : {"ascii.vtk", "binary.vtk", "old-ascii.vtk", "old-binary.vtk", "binary.stl",
                             "ascii.ply", "binary.ply"}) {
        ASSERT_NO_THROW(io::readDataset(dir.file(name))) << name;
        const std::string bytes = readBytes(dir.file(name));
        for (int percent = 5; percent <= 95; percent += 5) {
            const std::string cut = "cut" + std::to_string(percent) + "_" + name;
            writeText(dir.file(cut), bytes.substr(0, bytes.size() * percent / 100));
            expectReadError<FormatError>(dir.file(cut), cut);
        }
    }
}

TEST(IoReaders, GarbageBytesAreFormatError) {
    ScratchDir dir;
    std::string garbage(4096, '\0');
    uint32_t state = 12345;  // our own LCG: the same bytes everywhere
    for (auto& c : garbage) {
        state = state * 1664525u + 1013904223u;
        c = static_cast<char>(state >> 24);
    }
    for (const char* name :
         {"g.vtp", "g.vtu", "g.vtk", "g.ply", "g.obj", "g.stl", "g.e", "g.case", "g.pvd"}) {
        writeText(dir.file(name), garbage);
        expectReadError<FormatError>(dir.file(name), name);
    }
}

TEST(IoReaders, MismatchedArrayLengthIsFormatError) {
    ScratchDir dir;
    writeText(dir.file("short.vtp"), tinyVtp("1 0 0 1 0 0"));  // 2 vectors for 3 points
    expectReadError<FormatError>(dir.file("short.vtp"), "short.vtp", "U");
    writeText(dir.file("ok.vtp"), tinyVtp("1 0 0 1 0 0 1 0 0"));
    EXPECT_EQ(io::readDataset(dir.file("ok.vtp")).steps[0].mesh.triangleCount(), 1u);
}

TEST(IoReaders, OutOfRangeConnectivityIsFormatError) {
    ScratchDir dir;
    writeText(dir.file("index.vtp"), tinyVtp("1 0 0 1 0 0 1 0 0", "0 1 99"));
    expectReadError<FormatError>(dir.file("index.vtp"), "index.vtp", "point index 99");
    // The same through VTK's legacy writer, which does not check indices either.
    auto grid = makeGrid(1, 1, true);
    vtkIdType bad[3] = {0, 1, 42};
    grid->GetPolys()->InsertNextCell(3, bad);
    grid->GetCellData()->Initialize();  // keep the cell arrays' length consistent
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetInputData(grid);
    w->SetFileName(dir.file("index.vtk").c_str());
    ASSERT_EQ(w->Write(), 1);
    expectReadError<FormatError>(dir.file("index.vtk"), "index.vtk", "point index 42");
}

TEST(IoReaders, NanVectorIsFormatError) {
    ScratchDir dir;
    auto grid = makeGrid(2, 2);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    grid->GetPointData()->GetArray("U")->SetTuple3(4, nan, 0, 0);
    writeVtp(grid, dir.file("nan.vtp"));
    expectReadError<FormatError>(dir.file("nan.vtp"), "nan.vtp", "'U' has a non-finite vector");
    // A NaN in a cell vector reaches the points around it.
    grid = makeGrid(2, 2);
    grid->GetCellData()->GetArray("cellVec")->SetTuple3(0, 0, nan, 0);
    writeVtp(grid, dir.file("cellnan.vtp"));
    expectReadError<FormatError>(dir.file("cellnan.vtp"), "cellnan.vtp", "'cellVec'");
}

TEST(IoReaders, PointsWithoutTrianglesIsFormatError) {
    ScratchDir dir;
    auto grid = makeGrid(2, 1);
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    vtkIdType line[2] = {0, 1};
    lines->InsertNextCell(2, line);
    grid->SetPolys(vtkSmartPointer<vtkCellArray>::New());
    grid->SetLines(lines);
    grid->GetCellData()->Initialize();
    writeVtp(grid, dir.file("lines.vtp"));
    expectReadError<FormatError>(dir.file("lines.vtp"), "lines.vtp", "no triangles");
    writeText(dir.file("comments.obj"), "# nothing here\n");
    expectReadError<FormatError>(dir.file("comments.obj"), "comments.obj", "no points");
}

TEST(IoReaders, PvdErrorsNameCollectionAndMember) {
    ScratchDir dir;
    writeText(dir.file("missing.pvd"),
              "<VTKFile type=\"Collection\"><Collection>"
              "<DataSet timestep=\"0\" file=\"gone.vtp\"/></Collection></VTKFile>");
    expectReadError<IoError>(dir.file("missing.pvd"), "missing.pvd", "gone.vtp: cannot open");
    writeText(dir.file("bad.vtp"), "<VTKFile");
    writeText(dir.file("bad.pvd"),
              "<VTKFile type=\"Collection\"><Collection>"
              "<DataSet timestep=\"0\" file=\"bad.vtp\"/></Collection></VTKFile>");
    expectReadError<FormatError>(dir.file("bad.pvd"), "bad.pvd", "bad.vtp");
    writeText(dir.file("none.pvd"), "<VTKFile type=\"Collection\"><Collection/></VTKFile>");
    expectReadError<FormatError>(dir.file("none.pvd"), "none.pvd", "no DataSet");
}

TEST(IoReaders, BadFilesPrintNothing) {
    ScratchDir dir;
    writeText(dir.file("cut.vtp"), tinyVtp("1 0 0 1 0 0 1 0 0").substr(0, 200));
    writeText(dir.file("text.vtk"), "hello\n");
    writeText(dir.file("x.ply"), "ply\nformat ascii 1.0\nelement vertex 9\nend_header\n1 2\n");
    writeText(dir.file("x.case"), "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: missing.geo\n");
    ::testing::internal::CaptureStderr();
    for (const char* name : {"cut.vtp", "text.vtk", "x.ply", "x.case"})
        EXPECT_THROW(io::readDataset(dir.file(name)), FormatError) << name;
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST(IoReaders, MalformedCellsAreFormatErrorsNotCrashes) {
    ScratchDir dir;
    const std::string points = "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n";
    const std::pair<std::string, std::string> cases[] = {
        // Old layout: a count larger than the list, a list shorter than declared, a
        // token that is not a number (each crashed VTK 9.1's reader).
        {"# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n" + points + "POLYGONS 1 5\n900 0 1 2 3\n",
         "does not fit"},
        {"# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n" + points + "POLYGONS 2 5\n3 0 1 2 3\n",
         "does not fit"},
        {"# vtk DataFile Version 4.2\nt\nASCII\nDATASET POLYDATA\n" + points + "POLYGONS 1 5\n4 0 x 2 3\n",
         "not an integer"},
        {"# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
             "CELLS 1 5\n900 0 1 2 3\nCELL_TYPES 1\n9\n",
         "does not fit"},
        // New layout: a two-point polygon (crashes vtkCellDataToPointData), a
        // hexahedron with five points, an unknown cell type.
        {"# vtk DataFile Version 5.1\nt\nASCII\nDATASET POLYDATA\n" + points +
             "POLYGONS 3 5\nOFFSETS vtktypeint64\n0 2 5\nCONNECTIVITY vtktypeint64\n0 1 0 2 3\n"
             "CELL_DATA 2\nFIELD FieldData 1\nc 3 2 float\n1 0 0 0 1 0\n",
         "polygon 0 has 2 points"},
        {"# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
             "CELLS 2 5\nOFFSETS vtktypeint64\n0 5\nCONNECTIVITY vtktypeint64\n0 1 2 3 0\nCELL_TYPES 1\n12\n",
         "5 points, 8 expected"},
        {"# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
             "CELLS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\nCELL_TYPES 1\n200\n",
         "unknown type 200"},
        {"# vtk DataFile Version \x8d.1\nt\nASCII\nDATASET POLYDATA\n" + points, "first line"},
    };
    int i = 0;
    for (const auto& [text, why] : cases) {
        const std::string name = "cells" + std::to_string(i++) + ".vtk";
        writeText(dir.file(name), text);
        expectReadError<FormatError>(dir.file(name), name, why);
    }
}

TEST(IoReaders, BrokenExodusIsFormatErrorWithoutOutput) {
    ScratchDir dir;
    auto grid = vtkSmartPointer<vtkAppendFilter>::New();
    grid->AddInputData(makeGrid(6, 5));
    grid->Update();
    auto w = vtkSmartPointer<vtkExodusIIWriter>::New();
    w->SetInputData(grid->GetOutput());
    w->SetFileName(dir.file("grid.e").c_str());
    w->WriteAllTimeStepsOff();
    ASSERT_EQ(w->Write(), 1);
    ASSERT_NO_THROW(io::readDataset(dir.file("grid.e")));
    const std::string bytes = readBytes(dir.file("grid.e"));
    ::testing::internal::CaptureStderr();
    for (int percent = 5; percent <= 95; percent += 10) {
        const std::string cut = "cut" + std::to_string(percent) + ".e";
        writeText(dir.file(cut), bytes.substr(0, bytes.size() * percent / 100));
        expectReadError<FormatError>(dir.file(cut), cut);
    }
    writeText(dir.file("text.exo"), "not netcdf at all");
    expectReadError<FormatError>(dir.file("text.exo"), "text.exo", "not an Exodus II file");
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");  // the Exodus library never got to print
}
