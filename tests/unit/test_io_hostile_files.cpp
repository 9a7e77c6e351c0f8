// Hostile files, each the reason one of the former format pre-parsers existed (EnSight
// counts beyond the file, XML compression headers, Exodus connectivity and missing
// variables), and CGNS files cut short, with counts beyond the file or links leading
// nowhere: fed to the reader process as they are, each is refused within 5 s with a
// typed error naming the file, whatever VTK's reader does with it (an error, a crash, a
// runaway allocation or loop stopped by the child's limits). Old-layout legacy cell lists
// are still checked before VTK (checks.h says why) and refused the same way.
// "Within 5 s" is asserted on the reader's CPU time, which a loaded machine does not
// stretch; the wall clock only has to stay under the library's deadline (30 s).
#include "core/errors.h"
#include "io/dataset_reader.h"

#include "cgns_cases.h"
#include "test_io_common.h"

#include <vtkAppendFilter.h>
#include <vtkExodusIIWriter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdint>
#include <cstring>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

// Reads `path`; expects a flowsurf error naming it, within 5 s (see above).
void expectRefusedQuickly(const std::string& path) {
    SCOPED_TRACE(path);
    std::string what = "no exception";
    const Took took = timed([&] {
        try {
            io::readDataset(path);
        } catch (const Error& e) {
            what = e.what();
        }
    });
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.find("sandbox"), std::string::npos) << what;  // reading needs no forbidden call
    EXPECT_LT(took.cpu, 5.0) << what;
    EXPECT_EQ(what.find("took longer"), std::string::npos) << what;
}

// --- EnSight Gold: counts beyond the file (VTK allocates for them and loops at its end) ---
std::string caseFile(const ScratchDir& dir, const std::string& model = "mesh.geo") {
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\n\nGEOMETRY\nmodel: " + model + "\n");
    return path;
}

// The unit square as two triangles, one value per line, with the given counts.
std::string asciiSquare(const std::string& coordinates, const std::string& elements,
                        const std::string& block = "tria3") {
    std::string s = "square\ngeometry\nnode id off\nelement id off\npart\n         1\nsquare\ncoordinates\n" +
                    coordinates + "\n";
    for (const char* v : {"0", "1", "1", "0", "0", "0", "1", "1", "0", "0", "0", "0"}) s += std::string(v) + "\n";
    return s + block + "\n" + elements + "\n         1         2         3\n         1         3         4\n";
}

// The same square in C binary, in either byte order.
std::string binarySquare(bool bigEndian, int32_t coordinates, int32_t elements) {
    std::string b;
    auto str = [&](const std::string& s) { b += s + std::string(80 - s.size(), '\0'); };
    auto i32 = [&](int32_t v) {
        uint32_t u;
        std::memcpy(&u, &v, 4);
        for (int i = 0; i < 4; ++i) b += char(u >> (8 * (bigEndian ? 3 - i : i)));
    };
    auto f32 = [&](float v) {
        int32_t i;
        std::memcpy(&i, &v, 4);
        i32(i);
    };
    for (const char* s : {"C Binary", "square", "geometry", "node id off", "element id off", "part"}) str(s);
    i32(1);
    str("square");
    str("coordinates");
    i32(coordinates);
    for (float v : {0, 1, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0}) f32(v);
    str("tria3");
    i32(elements);
    for (int32_t v : {1, 2, 3, 1, 3, 4}) i32(v);
    return b;
}

}  // namespace

TEST(IoHostileFiles, EnSightCountsBeyondTheFile) {
    ScratchDir dir;
    const std::string geo = dir.file("mesh.geo"), path = caseFile(dir);
    const std::string cases[] = {
        asciiSquare("100000000", "2"), asciiSquare("4", "50000000"), asciiSquare("4", "900"),
        asciiSquare("-4", "2"),
        // nsided: the connectivity line VTK waits for is missing; comment lines are not data.
        asciiSquare("4", "2").substr(0, asciiSquare("4", "2").find("tria3")) +
            "nsided\n2\n4\n4\n         1         2         3         4\n#\n\n",
        binarySquare(false, 1 << 30, 2), binarySquare(true, 1 << 30, 2), binarySquare(false, 4, 5000),
        binarySquare(true, 4, 5000), "C Binary\n"};
    for (const auto& text : cases) {
        writeText(geo, text);
        expectRefusedQuickly(path);
    }
}

TEST(IoHostileFiles, EnSightStepCountBeyondTheCaseFile) {
    ScratchDir dir;
    writeText(dir.file("mesh.geo"), asciiSquare("4", "2"));
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: 1 mesh.geo\nTIME\ntime set: 1\n"
                    "number of steps: 1000000000\ntime values: 0\n");
    expectRefusedQuickly(path);
}

TEST(IoHostileFiles, EnSightSeriesWithOneBadGeometryFile) {
    ScratchDir dir;
    const std::string path = dir.file("t.case");
    writeText(path, "FORMAT\ntype: ensight gold\nGEOMETRY\nmodel: 1 mesh.geo**\nTIME\ntime set: 1\n"
                    "number of steps: 3\nfilename start number: 0\nfilename increment: 2\ntime values: 0 1 2\n");
    for (const char* step : {"00", "02"}) writeText(dir.file(std::string("mesh.geo") + step), binarySquare(false, 4, 2));
    writeText(dir.file("mesh.geo04"), binarySquare(false, 4, 70000));
    expectRefusedQuickly(path);
}

// --- legacy .vtk: old-layout "count id id ..." cell lists, walked unchecked by VTK ------
TEST(IoHostileFiles, LegacyCellListsThatDoNotAddUp) {
    ScratchDir dir;
    const std::string head = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET ";
    const std::string points = "POINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\n";
    const std::string cases[] = {
        head + "POLYDATA\n" + points + "POLYGONS 1 5\n900 0 1 2 3\n",
        head + "POLYDATA\n" + points + "POLYGONS 2 5\n3 0 1 2 3\n",
        head + "POLYDATA\n" + points + "POLYGONS 1 5\n4 0 x 2 3\n",
        head + "UNSTRUCTURED_GRID\n" + points + "CELLS 1 5\n900 0 1 2 3\nCELL_TYPES 1\n9\n",
        head + "POLYDATA\n" + points + "POLYGONS 1 2000000000\n3 0 1 2\n",
        "# vtk DataFile Version \x8d.1\nt\nASCII\nDATASET POLYDATA\n" + points,
    };
    int i = 0;
    for (const auto& text : cases) {
        const std::string name = dir.file("cells" + std::to_string(i++) + ".vtk");
        writeText(name, text);
        expectRefusedQuickly(name);
    }
}

// --- VTK XML: compressed arrays' block tables ---------------------------------------------
TEST(IoHostileFiles, XmlCompressionHeaders) {
    ScratchDir dir;
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetInputData(makeGrid(4, 4));
    w->SetFileName(dir.file("zlib.vtp").c_str());
    w->SetDataModeToAppended();
    w->EncodeAppendedDataOff();
    w->SetCompressorTypeToZLib();
    ASSERT_EQ(w->Write(), 1);
    const std::string bytes = readBytes(dir.file("zlib.vtp"));
    const size_t data = bytes.find('_', bytes.find("<AppendedData")) + 1;
    // The first array's block count: 0xA4000000 (a 10 GiB table), or 0 for a non-empty array.
    for (const auto& [name, count] : {std::pair<const char*, std::string>{"blocks.vtp", std::string("\0\0\0\xA4", 4)},
                                      {"none.vtp", std::string(4, '\0')}}) {
        std::string hostile = bytes;
        hostile.replace(data, 4, count);
        writeText(dir.file(name), hostile);
        expectRefusedQuickly(dir.file(name));
    }
}

// --- Exodus II: connectivity naming a node that does not exist, a variable missing --------
TEST(IoHostileFiles, ExodusConnectivityAndMissingVariables) {
    ScratchDir dir;
    auto grid = vtkSmartPointer<vtkAppendFilter>::New();
    grid->AddInputData(makeGrid(6, 5));
    grid->Update();
    auto w = vtkSmartPointer<vtkExodusIIWriter>::New();
    w->SetInputData(grid->GetOutput());
    w->SetFileName(dir.file("grid.e").c_str());
    w->WriteAllTimeStepsOff();
    ASSERT_EQ(w->Write(), 1);
    const std::string bytes = readBytes(dir.file("grid.e"));
    // The first quad's nodes (1-based, big-endian int32): 1 2 9 8; node 9 becomes 2^31 - 1.
    const std::string quad("\0\0\0\1\0\0\0\2\0\0\0\x09\0\0\0\x08", 16);
    const size_t at = bytes.find(quad);
    ASSERT_NE(at, std::string::npos);
    std::string hostile = bytes;
    hostile.replace(at + 8, 4, std::string("\x7f\xff\xff\xff", 4));
    writeText(dir.file("node.e"), hostile);
    expectRefusedQuickly(dir.file("node.e"));
    for (const char* variable : {"coordx", "connect1"}) {
        hostile = bytes;
        const size_t name = hostile.find(variable);
        ASSERT_NE(name, std::string::npos) << variable;
        hostile[name] = 'X';  // the variable is no longer there by its name
        const std::string path = dir.file(std::string("no_") + variable + ".e");
        writeText(path, hostile);
        expectRefusedQuickly(path);
    }
}

// --- CGNS: truncated files, counts beyond the file, links that lead nowhere ----------------
// Written with libcgns (tests/cgns/cgns_cases.h), then damaged: HDF5 and ADF cut short,
// a zone claiming 2^31 - 1 vertices, a section or BC ranging over two billion elements,
// and coordinates linked to a missing file, a missing node, a file outside the folder the
// reader may read and the file itself.
TEST(IoHostileFiles, CgnsTruncatedCountBombsAndWrongLinks) {
    namespace cases = flowsurf::testing_cgns;
    ScratchDir dir;
    for (auto backend : {cases::Backend::Hdf5, cases::Backend::Adf}) {
        const std::string tag = backend == cases::Backend::Hdf5 ? "hdf5" : "adf";
        const std::string good = dir.file("good_" + tag + ".cgns");
        cases::writeUnstructuredBox(good, backend);
        const std::string bytes = readBytes(good);
        for (size_t keep : {bytes.size() / 2, bytes.size() * 3 / 4, size_t(600)}) {  // ADF's last block may be unused
            const std::string path = dir.file("cut_" + std::to_string(keep) + "_" + tag + ".cgns");
            writeText(path, bytes.substr(0, keep));
            expectRefusedQuickly(path);
        }
        const struct {
            const char* name;
            const char* node;
            std::vector<int> values;
        } bombs[] = {{"zone", "/Base/Fluid", {0x7fffffff, 16, 0}},
                     {"section", "/Base/Fluid/floor/ElementRange", {25, 2000000000}},
                     {"bc", "/Base/Fluid/ZoneBC/floor/PointRange", {25, 2000000000}}};
        for (const auto& bomb : bombs) {
            const std::string path = dir.file(std::string("bomb_") + bomb.name + "_" + tag + ".cgns");
            writeText(path, bytes);
            cases::overwriteNode(path, bomb.node, bomb.values);
            expectRefusedQuickly(path);
        }
        const std::string self = dir.file("self_" + tag + ".cgns");
        const struct {
            std::string file, target, node;
        } links[] = {{dir.file("missing_file_" + tag + ".cgns"), "nosuch.cgns", "/Base/Fluid/GridCoordinates"},
                     {dir.file("missing_node_" + tag + ".cgns"), "good_" + tag + ".cgns", "/Base/Fluid/NoSuchNode"},
                     {dir.file("outside_" + tag + ".cgns"), "/etc/passwd", "/Base/Fluid/GridCoordinates"},
                     {self, "self_" + tag + ".cgns", "/Base/Fluid/GridCoordinates"}};
        for (const auto& link : links) {
            cases::writeLinkedBox(link.file, backend, link.target, link.node);
            expectRefusedQuickly(link.file);
        }
    }
}
