// CGNS files written with Debian's libcgns (tests/cgns/cgns_cases.h), read as a user gets
// them: a volume's wall patches by default (by BC type and through a family), other patches
// by BC or family name, the volume's boundary when there is no wall BC, structured zones in
// several bases, HDF5 and ADF, solutions at vertices and cell centres, BaseIterativeData's
// time steps and a file series. Each surface is compared with the same surface written as a
// VTK legacy file from the generator's own points and formulas.
#include "cgns_cases.h"
#include "test_io_common.h"

#include "io/series_reader.h"

#include <cstdio>
#include <cstring>
#include <set>
#include <tuple>

using namespace flowsurf;
using namespace flowsurf::testing_io;
namespace cases = flowsurf::testing_cgns;

namespace {

// A mesh as the sorted list of its vertices (position and every array's values, rounded)
// and of its triangles (as their sorted corner positions): equal for the same surface
// whatever the order its reader numbered it in.
struct Canonical {
    std::vector<std::string> vertices, triangles;
    std::set<std::string> arrays;
};

std::string rounded(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.5f", std::abs(v) < 5e-6 ? 0.0 : v);
    return s;
}
std::string position(const glm::vec3& p) { return rounded(p.x) + " " + rounded(p.y) + " " + rounded(p.z); }

Canonical canonical(const core::SurfaceMesh& m) {
    Canonical c;
    for (size_t i = 0; i < m.vertexCount(); ++i) {
        std::string v = position(m.positions[i]);
        for (const auto& f : m.fields) v += " " + f.name + "=" + position(f.values[i]);
        for (const auto& s : m.scalars) v += " " + s.name + "=" + rounded(s.values[i]);
        c.vertices.push_back(v);
    }
    for (const auto& t : m.triangles) {
        std::vector<std::string> corners{position(m.positions[t.x]), position(m.positions[t.y]), position(m.positions[t.z])};
        std::sort(corners.begin(), corners.end());
        c.triangles.push_back(corners[0] + " | " + corners[1] + " | " + corners[2]);
    }
    std::sort(c.vertices.begin(), c.vertices.end());
    std::sort(c.triangles.begin(), c.triangles.end());
    for (const auto& f : m.fields) c.arrays.insert(f.name);
    for (const auto& s : m.scalars) c.arrays.insert(s.name);
    return c;
}

void expectSameSurface(const core::SurfaceMesh& cgns, const std::string& expectedVtk) {
    const core::SurfaceMesh expected = io::openSeries(expectedVtk)->load(0);
    const Canonical a = canonical(cgns), b = canonical(expected);
    EXPECT_EQ(a.arrays, b.arrays);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (size_t i = 0; i < a.vertices.size(); ++i) ASSERT_EQ(a.vertices[i], b.vertices[i]) << "vertex " << i;
    EXPECT_EQ(a.triangles, b.triangles);
}

core::SurfaceMesh firstStep(const std::string& path, const io::SourceOptions& options = {}) {
    return io::openSeries(path, options)->load(0);
}

const io::PatchInfo* findPatch(const io::FileInfo& info, const std::string& name) {
    for (const auto& p : info.patches)
        if (p.name == name) return &p;
    return nullptr;
}

}  // namespace

// The walls by default: floor (BCWall) and roof (FamilySpecified, family Walls = BCWallViscous),
// with the vertex solution exact and the cell-centred one taken from each wall face's cell.
TEST(IoCgns, UnstructuredVolumeGivesItsWallsAsTheVtkSurface) {
    ScratchDir dir;
    for (auto backend : {cases::Backend::Hdf5, cases::Backend::Adf}) {
        const std::string file = dir.file(backend == cases::Backend::Hdf5 ? "box.cgns" : "box_adf.cgns");
        SCOPED_TRACE(file);
        cases::writeUnstructuredBox(file, backend, dir.file("box.expected.vtk"));
        const core::SurfaceMesh m = firstStep(file);
        EXPECT_EQ(m.triangleCount(), 32u);  // 2 walls x 8 quadrilaterals
        expectSameSurface(m, dir.file("box.expected.vtk"));
        ASSERT_NE(m.findScalar("Temperature"), nullptr);  // a cell-centred solution, found unasked
    }
}

// The layouts of other meshers: MIXED sections with BCs as element lists and ranges, and
// polyhedra (NGON_n faces, NFACE_n cells) with BCs as ranges of faces.
TEST(IoCgns, MixedSectionsAndPolyhedraGiveTheSameWalls) {
    ScratchDir dir;
    const std::string file = dir.file("mixed.cgns");
    cases::writeMixedBox(file, cases::Backend::Hdf5, dir.file("mixed.expected.vtk"));
    expectSameSurface(firstStep(file), dir.file("mixed.expected.vtk"));
    const std::string poly = dir.file("polyhedra.cgns");  // NGON_n faces, NFACE_n cells
    cases::writePolyhedralBox(poly, cases::Backend::Adf);
    expectSameSurface(firstStep(poly), dir.file("mixed.expected.vtk"));
}

TEST(IoCgns, PatchesPickedByBcNameOrFamily) {
    ScratchDir dir;
    const std::string file = dir.file("box.cgns");
    cases::writeUnstructuredBox(file, cases::Backend::Hdf5);
    EXPECT_EQ(firstStep(file, {.patches = "inlet"}).triangleCount(), 8u);        // 4 faces
    EXPECT_EQ(firstStep(file, {.patches = "Walls"}).triangleCount(), 16u);       // the family: roof
    EXPECT_EQ(firstStep(file, {.patches = "in.*|out.*"}).triangleCount(), 16u);  // both ends
    EXPECT_EQ(firstStep(file, {.patches = "outlet"}).bounds().lo.x, 2.0f);       // a BC given by its vertices
    try {
        firstStep(file, {.patches = "wing"});
        FAIL() << "no ConfigError";
    } catch (const ConfigError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(file), std::string::npos) << what;
        EXPECT_NE(what.find("roof (BCWallViscous, family Walls)"), std::string::npos) << what;
        EXPECT_NE(what.find("inlet (BCInflow)"), std::string::npos) << what;
    }
}

TEST(IoCgns, InfoListsEveryBoundaryWithItsTypeAndWhatIsRead) {
    ScratchDir dir;
    const std::string file = dir.file("box.cgns");
    cases::writeUnstructuredBox(file, cases::Backend::Hdf5);
    const io::FileInfo info = io::inspectFile(file);
    EXPECT_NE(info.format.find("CGNS (HDF5"), std::string::npos) << info.format;
    EXPECT_NE(info.format.find("wall patches"), std::string::npos) << info.format;
    ASSERT_EQ(info.patches.size(), 5u);
    const io::PatchInfo* roof = findPatch(info, "roof");
    ASSERT_NE(roof, nullptr);
    EXPECT_EQ(roof->type, "BCWallViscous");
    EXPECT_EQ(roof->family, "Walls");
    EXPECT_TRUE(roof->read);
    ASSERT_NE(findPatch(info, "inlet"), nullptr);
    EXPECT_EQ(findPatch(info, "inlet")->type, "BCInflow");
    EXPECT_FALSE(findPatch(info, "inlet")->read);
    EXPECT_EQ(findPatch(info, "floor")->faces, 8u);
    const std::string text = io::formatFileInfo(info);
    EXPECT_NE(text.find("Boundaries   5"), std::string::npos) << text;
    EXPECT_NE(text.find("Temperature"), std::string::npos) << text;  // listed, though cell-centred
    // --patches changes what is read, and info says so.
    const io::FileInfo inlet = io::inspectFile(file, {.patches = "inlet"});
    EXPECT_TRUE(findPatch(inlet, "inlet")->read);
    EXPECT_FALSE(findPatch(inlet, "roof")->read);
}

TEST(IoCgns, StructuredZonesInSeveralBases) {
    ScratchDir dir;
    const std::string file = dir.file("blocks.cgns");
    cases::writeStructuredBlocks(file, cases::Backend::Hdf5, dir.file("blocks.expected.vtk"));
    const core::SurfaceMesh m = firstStep(file);
    EXPECT_EQ(m.triangleCount(), 3u * 16u);  // three zones' j = 1 faces, 4 x 2 quadrilaterals each
    expectSameSurface(m, dir.file("blocks.expected.vtk"));
    ASSERT_NE(m.findScalar("Density"), nullptr);  // cell-centred, from the cells on the wall
    const io::FileInfo info = io::inspectFile(file);
    EXPECT_EQ(info.patches.size(), 6u);
    ASSERT_NE(findPatch(info, "Block3/wall"), nullptr);  // the zone in the second base
    EXPECT_TRUE(findPatch(info, "Block3/wall")->read);
    EXPECT_FALSE(findPatch(info, "Block1/farfield")->read);
}

TEST(IoCgns, VolumeWithoutWallsGivesItsBoundarySurface) {
    ScratchDir dir;
    const std::string file = dir.file("nobc.cgns");
    cases::writeBoxWithoutBcs(file, cases::Backend::Adf, dir.file("nobc.expected.vtk"));
    expectSameSurface(firstStep(file), dir.file("nobc.expected.vtk"));
    EXPECT_NE(io::inspectFile(file).format.find("boundary surface"), std::string::npos);
}

TEST(IoCgns, SurfaceZoneIsShownWhole) {
    ScratchDir dir;
    const std::string file = dir.file("surface.cgns");
    cases::writeSurfaceZone(file, cases::Backend::Adf, dir.file("surface.expected.vtk"));
    expectSameSurface(firstStep(file), dir.file("surface.expected.vtk"));
}

TEST(IoCgns, IterativeDataIsATimeSeriesStreamedStepByStep) {
    ScratchDir dir;
    const std::string file = dir.file("series.cgns");
    cases::writeUnstructuredSeries(file, cases::Backend::Hdf5, dir.file("series_%d.vtk"));
    auto steps = io::openSeries(file);
    ASSERT_EQ(steps->count(), 3u);
    EXPECT_DOUBLE_EQ(steps->time(1), 0.5);
    for (size_t i : {2u, 0u, 1u}) {  // any order, each step its own solution
        SCOPED_TRACE(i);
        char expected[64];
        std::snprintf(expected, sizeof expected, "series_%zu.vtk", i);
        expectSameSurface(steps->load(i), dir.file(expected));
    }
}

// A moving mesh (GridCoordinatesPointers): the walls move with their coordinates.
TEST(IoCgns, MovingMeshMovesTheWalls) {
    ScratchDir dir;
    const std::string file = dir.file("moving.cgns");
    cases::writeUnstructuredSeries(file, cases::Backend::Adf, {}, true);
    auto steps = io::openSeries(file);
    ASSERT_EQ(steps->count(), 3u);
    EXPECT_FLOAT_EQ(steps->load(0).bounds().lo.z, 0.0f);
    EXPECT_FLOAT_EQ(steps->load(2).bounds().lo.z, 0.5f);  // lifted by 0.5 t at t = 1
    EXPECT_FLOAT_EQ(steps->load(1).bounds().hi.z, 1.25f);
}

// FlowSolutionPointers naming a solution the zone lacks: read, and said (VTK's reader would
// show another solution for that step without a word).
TEST(IoCgns, SolutionPointerToNothingIsWarned) {
    ScratchDir dir;
    const std::string file = dir.file("pointers.cgns");
    cases::writeUnstructuredSeries(file, cases::Backend::Hdf5);
    std::vector<int> names(24, 0x20202020);  // 3 names of 32 blanks
    std::memcpy(names.data() + 8, "Gone", 4);  // the second step's
    cases::overwriteNode(file, "/Base/Fluid/ZoneIterativeData/FlowSolutionPointers", names);
    ::testing::internal::CaptureStderr();
    auto steps = io::openSeries(file);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(steps->count(), 3u);
    EXPECT_NE(err.find("FlowSolutionPointers names 'Gone' for time step 2"), std::string::npos) << err;
}

TEST(IoCgns, FileSeriesReadsTheSamePatchesOfEveryFile) {
    ScratchDir dir;
    for (int i = 0; i < 2; ++i) cases::writeUnstructuredBox(dir.file("run_" + std::to_string(i) + ".cgns"), cases::Backend::Hdf5);
    auto steps = io::openSeries(dir.file("run_*.cgns"), {.patches = "inlet"});
    ASSERT_EQ(steps->count(), 2u);
    EXPECT_EQ(steps->load(1).triangleCount(), 8u);
}
