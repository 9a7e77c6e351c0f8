// --field skin-friction on CGNS volume results (tests/cgns's writeCouetteBox: an exact linear
// shear between a floor at rest and a moving roof), structured and unstructured, with the
// velocity at the vertices or at the cell centres: the one-cell wall stress is exact there,
// so every wall point must carry it; and the errors a user meets (no velocity, no wall read,
// a surface-only file), each naming the file.
#include "cgns_cases.h"
#include "test_io_common.h"

#include "io/series_reader.h"

#include <cmath>

using namespace flowsurf;
using namespace flowsurf::testing_io;
namespace cases = flowsurf::testing_cgns;

namespace {

core::SurfaceMesh readSkinFriction(const std::string& path, double viscosity, const std::string& patches = {}) {
    io::SourceOptions o;
    o.skinFriction = true;
    o.viscosity = viscosity;
    o.patches = patches;
    return io::openSeries(path, o)->load(0);
}

// Every point on the floor (y = 0) must carry (floor, 0, 0), every point on the roof (y = 1)
// (roof, 0, 0); returns how many points were on each.
std::pair<size_t, size_t> expectWallStress(const core::SurfaceMesh& m, double floor, double roof) {
    const core::VectorField* tau = m.findField("skin-friction");
    EXPECT_NE(tau, nullptr);
    if (!tau) return {0, 0};
    size_t onFloor = 0, onRoof = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const float y = m.positions[i].y;
        const bool isFloor = std::abs(y) < 1e-6f, isRoof = std::abs(y - 1.0f) < 1e-6f;
        EXPECT_TRUE(isFloor || isRoof) << "point " << i << " at y " << y << " is on no wall";
        if (!isFloor && !isRoof) continue;
        (isFloor ? onFloor : onRoof)++;
        EXPECT_NEAR(tau->values[i].x, isFloor ? floor : roof, 1e-5 * std::abs(floor)) << "point " << i << " y " << y;
        EXPECT_NEAR(tau->values[i].y, 0.0, 1e-5 * std::abs(floor)) << "point " << i;
        EXPECT_NEAR(tau->values[i].z, 0.0, 1e-5 * std::abs(floor)) << "point " << i;
    }
    return {onFloor, onRoof};
}

std::string cgnsFile(const ScratchDir& dir, cases::CouetteVelocity velocity, bool structured) {
    const std::string file = dir.file(std::string(structured ? "structured" : "unstructured") + ".cgns");
    cases::writeCouetteBox(file, cases::Backend::Hdf5, velocity, structured);
    return file;
}

constexpr double kNu = 0.5;
constexpr double kGamma = cases::kCouetteShear;

}  // namespace

TEST(SkinFrictionCgns, VertexSolutionGivesNuTimesShearOnBothWallsStructuredAndUnstructured) {
    ScratchDir dir;
    for (bool structured : {false, true}) {
        SCOPED_TRACE(structured ? "structured" : "unstructured");
        const core::SurfaceMesh m = readSkinFriction(cgnsFile(dir, cases::CouetteVelocity::Vertex, structured), kNu);
        // 5 x 3 points on each wall; the roof moves with the fluid, so its stress drags it back.
        const auto [onFloor, onRoof] = expectWallStress(m, kNu * kGamma, -kNu * kGamma);
        EXPECT_EQ(onFloor, 15u);
        EXPECT_EQ(onRoof, 15u);
    }
}

TEST(SkinFrictionCgns, CellCentredSolutionTakesTheWallsAtRest) {
    ScratchDir dir;
    for (bool structured : {false, true}) {
        SCOPED_TRACE(structured ? "structured" : "unstructured");
        const core::SurfaceMesh m = readSkinFriction(cgnsFile(dir, cases::CouetteVelocity::CellCenter, structured), kNu);
        // Cell centres at y = 0.25 and 0.75: u = 0.5 γ and 1.5 γ over d = 0.25 from walls at rest.
        const auto [onFloor, onRoof] = expectWallStress(m, kNu * kGamma, 3 * kNu * kGamma);
        EXPECT_EQ(onFloor + onRoof, 30u);
    }
}

TEST(SkinFrictionCgns, WithoutViscosityTheMagnitudeIsTheShearAndTheLegendSaysRelative) {
    ScratchDir dir;
    const std::string file = cgnsFile(dir, cases::CouetteVelocity::Vertex, false);
    expectWallStress(readSkinFriction(file, 0), kGamma, -kGamma);
    io::SourceOptions o;
    o.skinFriction = true;
    const io::FileInfo info = io::inspectFile(file, o);
    EXPECT_NE(info.format.find("relative magnitude"), std::string::npos) << info.format;
}

TEST(SkinFrictionCgns, VolumeWithoutWallBcsTakesItsBoundarySurface) {
    ScratchDir dir;
    const std::string file = dir.file("nobc.cgns");
    cases::writeBoxWithoutBcs(file, cases::Backend::Adf);
    const core::SurfaceMesh m = readSkinFriction(file, kNu);
    ASSERT_NE(m.findField("skin-friction"), nullptr);
    EXPECT_EQ(m.vertexCount(), 5u * 3 * 3 - 3u);  // the box's boundary points (all but the 3 inner ones)
}

TEST(SkinFrictionCgns, InfoSaysWhereTheStressComesFrom) {
    ScratchDir dir;
    const std::string vertex = io::inspectFile(cgnsFile(dir, cases::CouetteVelocity::Vertex, false)).skinFriction;
    EXPECT_NE(vertex.find("Velocity (at the vertices)"), std::string::npos) << vertex;
    EXPECT_NE(vertex.find("floor, roof"), std::string::npos) << vertex;
    EXPECT_NE(vertex.find("relative magnitude unless --viscosity"), std::string::npos) << vertex;
    const std::string cell = io::inspectFile(cgnsFile(dir, cases::CouetteVelocity::CellCenter, true)).skinFriction;
    EXPECT_NE(cell.find("Velocity (cell-centred)"), std::string::npos) << cell;
    const std::string none = io::inspectFile(cgnsFile(dir, cases::CouetteVelocity::None, false)).skinFriction;
    EXPECT_EQ(none.rfind("not available", 0), 0u) << none;
}

TEST(SkinFrictionCgns, NoVelocityOrNoWallOrNoVolumeIsAnErrorNamingTheFile) {
    ScratchDir dir;
    const std::string noVelocity = cgnsFile(dir, cases::CouetteVelocity::None, false);
    try {
        readSkinFriction(noVelocity, kNu);
        ADD_FAILURE() << "no exception";
    } catch (const FieldError& e) {
        EXPECT_NE(std::string(e.what()).find(noVelocity), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no velocity"), std::string::npos) << e.what();
    }
    const std::string box = cgnsFile(dir, cases::CouetteVelocity::Vertex, true);
    try {
        readSkinFriction(box, kNu, "inlet");
        ADD_FAILURE() << "no exception";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find(box), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("none of the BCs read is a wall"), std::string::npos) << e.what();
    }
    const std::string surface = dir.file("surface.cgns");
    cases::writeSurfaceZone(surface, cases::Backend::Hdf5);
    try {
        readSkinFriction(surface, kNu);
        ADD_FAILURE() << "no exception";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find(surface), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("surface zones only"), std::string::npos) << e.what();
    }
}
