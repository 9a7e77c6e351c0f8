// OpenFOAM cases as they come, written here as small text files (unit hex cells): a
// decomposed case (processor* directories only), a moving mesh (points per time
// directory), units from `dimensions`, `info`'s patches with their fields, the
// warning when a field file has no entry for a patch, and a case as the tutorials are
// written and a solver leaves it (0/ skipped; a time directory VTK cannot parse left out).
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"
#include "test_io_common.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

using namespace flowsurf;
using namespace flowsurf::testing_io;

namespace {

std::string header(const std::string& cls, const std::string& object) {
    return "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class " + cls + ";\n    object " + object + ";\n}\n";
}

// The unit cube's faces in OpenFOAM's hex point order, each pointing out of the cell:
// 0: z = 0, 1: z = 1, 2: y = 0, 3: y = 1, 4: x = 0, 5: x = 1.
const char* const kCubeFaces[6] = {"4(0 3 2 1)", "4(4 5 6 7)", "4(0 1 5 4)", "4(3 7 6 2)", "4(0 4 7 3)", "4(1 2 6 5)"};

struct Patch {
    std::string name, type;
    std::vector<int> faces;   // of kCubeFaces
    std::string extra = "";   // more boundary entries (processor patches)
};

std::string cubePoints(double x0, double z0) {
    std::string s = "8\n(\n";
    for (int k = 0; k < 2; ++k)
        for (auto [x, y] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}})
            s.append("(").append(std::to_string(x0 + x) + " " + std::to_string(y) + " " + std::to_string(z0 + k) + ")\n");
    return s + ")\n";
}

// One cell in `dir`/constant/polyMesh: the cube moved by x0, its faces in patch order.
void writeCubeMesh(const fs::path& dir, double x0, const std::vector<Patch>& patches) {
    const fs::path mesh = dir / "constant/polyMesh";
    fs::create_directories(mesh);
    std::string faces, boundary;
    int count = 0;
    for (const auto& p : patches) {
        boundary += p.name + "\n{\n type " + p.type + ";\n nFaces " + std::to_string(p.faces.size()) +
                    ";\n startFace " + std::to_string(count) + ";\n" + p.extra + "}\n";
        for (int f : p.faces) faces += std::string(kCubeFaces[f]) + "\n", ++count;
    }
    writeText((mesh / "points").string(), header("vectorField", "points") + cubePoints(x0, 0));
    writeText((mesh / "faces").string(), header("faceList", "faces") + std::to_string(count) + "\n(\n" + faces + ")\n");
    std::string owners;  // every face belongs to cell 0
    for (int i = 0; i < count; ++i) owners += "0\n";
    writeText((mesh / "owner").string(), header("labelList", "owner") + std::to_string(count) + "\n(\n" + owners + ")\n");
    writeText((mesh / "neighbour").string(), header("labelList", "neighbour") + "0\n(\n)\n");
    writeText((mesh / "boundary").string(), header("polyBoundaryMesh", "boundary") + std::to_string(patches.size()) +
                                                "\n(\n" + boundary + ")\n");
}

// A volVectorField/volScalarField file; `entries` are the boundaryField's patch entries.
void writeField(const fs::path& timeDir, const std::string& name, const std::string& cls, const std::string& dims,
                const std::string& internal, const std::vector<std::pair<std::string, std::string>>& entries) {
    fs::create_directories(timeDir);
    std::string body = "dimensions [" + dims + "];\ninternalField uniform " + internal + ";\nboundaryField\n{\n";
    for (const auto& [patch, value] : entries) body += patch + "\n{\n type fixedValue;\n value uniform " + value + ";\n}\n";
    writeText((timeDir / name).string(), header(cls, name) + body + "}\n");
}

void writeControlDict(const fs::path& dir) {
    fs::create_directories(dir / "system");
    writeText((dir / "system/controlDict").string(),
              header("dictionary", "controlDict") + "application pimpleFoam;\nstartTime 0;\nendTime 1;\ndeltaT 1;\n");
    writeText((dir / "case.foam").string(), "");
}
void writeControlDict(const ScratchDir& dir) { writeControlDict(dir.path()); }

}  // namespace

// decomposePar's layout: two cells, one per processor directory, the face between them a
// processor patch on each side; the case folder has no mesh and no time directories.
TEST(OpenFoam, DecomposedCaseReadsEveryProcessorAndHidesProcessorPatches) {
    ScratchDir dir;
    writeControlDict(dir);
    const std::string proc = " inGroups 1(processor);\n matchTolerance 0.0001;\n transform unknown;\n";
    writeCubeMesh(dir.path() / "processor0", 0,
                  {{"walls", "wall", {0, 1, 2, 3, 4}}, {"procBoundary0to1", "processor", {5}, proc + " myProcNo 0;\n neighbProcNo 1;\n"}});
    writeCubeMesh(dir.path() / "processor1", 1,
                  {{"walls", "wall", {0, 1, 2, 3, 5}}, {"procBoundary1to0", "processor", {4}, proc + " myProcNo 1;\n neighbProcNo 0;\n"}});
    for (const char* p : {"processor0", "processor1"})
        for (const char* t : {"0", "0.5"}) {
            const std::string u = std::string("(") + (t[1] ? "2" : "1") + " 0 0)";
            writeField(dir.path() / p / t, "U", "volVectorField", "0 1 -1 0 0 0 0", u,
                       {{"walls", u}, {p == std::string("processor0") ? "procBoundary0to1" : "procBoundary1to0", u}});
        }

    // auto: the case folder has no mesh, so the processor directories are read; their 0/
    // (initial conditions) is skipped as a solved time exists, read when asked for.
    auto steps = io::openSeries(dir.file("case.foam"));
    ASSERT_EQ(steps->count(), 1u);
    EXPECT_DOUBLE_EQ(steps->time(0), 0.5);
    EXPECT_EQ(io::openSeries(dir.file("case.foam"), {.patches = {}, .foamCase = "auto", .zeroTime = true})->count(), 2u);
    const core::SurfaceMesh m = steps->load(0);
    EXPECT_EQ(m.triangleCount(), 20u) << "both cells' five wall faces, not the faces between processors";
    EXPECT_FLOAT_EQ(m.bounds().lo.x, 0.0f);
    EXPECT_FLOAT_EQ(m.bounds().hi.x, 2.0f);
    ASSERT_NE(m.findField("U"), nullptr);
    for (const auto& u : m.findField("U")->values) EXPECT_EQ(u, glm::vec3(2, 0, 0));

    const io::FileInfo info = io::inspectFile(dir.file("case.foam"));
    EXPECT_NE(info.format.find("decomposed, 2 processor directories"), std::string::npos) << info.format;
    ASSERT_EQ(info.parts.size(), 1u);
    EXPECT_EQ(info.parts[0].name, "walls");
    EXPECT_EQ(info.parts[0].faces, 10u);

    // Asked for the reconstructed case, which has no mesh: an error naming the case.
    EXPECT_THROW(io::openSeries(dir.file("case.foam"), {"", "reconstructed"})->load(0), FormatError);
    // The processors' 0/ as the tutorials write it (decomposePar copies it so): asked
    // for, it is left out by name and the solved time stays.
    for (const char* p : {"processor0", "processor1"}) {
        const std::string text = readBytes((dir.path() / p / "0/U").string());
        const size_t open = text.find("boundaryField\n{") + 15;  // right after the brace, as some write it
        writeText((dir.path() / p / "0/U").string(),
                  text.substr(0, open) + "#includeEtc \"caseDicts/setConstraintTypes\"\n" + text.substr(open));
    }
    ::testing::internal::CaptureStderr();
    auto tutorial = io::openSeries(dir.file("case.foam"), {.patches = {}, .foamCase = "auto", .zeroTime = true});
    const std::string err = ::testing::internal::GetCapturedStderr();
    ASSERT_EQ(tutorial->count(), 1u);
    EXPECT_DOUBLE_EQ(tutorial->time(0), 0.5);
    EXPECT_NE(err.find("left out time directory 0: "), std::string::npos) << err;
    // With a reconstructed mesh and 0/ only (a parallel run not reconstructed), auto
    // still takes the processor directories' solved time; asked for, the reconstructed
    // case's one time, 0/ (the only one, so not skipped).
    writeCubeMesh(dir.path(), 0, {{"walls", "wall", {0, 1, 2, 3, 4, 5}}});
    writeField(dir.path() / "0", "U", "volVectorField", "0 1 -1 0 0 0 0", "(1 0 0)", {{"walls", "(1 0 0)"}});
    auto decomposed = io::openSeries(dir.file("case.foam"));
    ASSERT_EQ(decomposed->count(), 1u);
    EXPECT_DOUBLE_EQ(decomposed->time(0), 0.5);
    auto reconstructed = io::openSeries(dir.file("case.foam"), {"", "reconstructed"});
    ASSERT_EQ(reconstructed->count(), 1u);
    EXPECT_DOUBLE_EQ(reconstructed->time(0), 0.0);
    // Asked for a decomposed case where there is none.
    ScratchDir plain;
    writeControlDict(plain);
    writeCubeMesh(plain.path(), 0, {{"walls", "wall", {0, 1, 2, 3, 4, 5}}});
    writeField(plain.path() / "0", "U", "volVectorField", "0 1 -1 0 0 0 0", "(1 0 0)", {{"walls", "(1 0 0)"}});
    EXPECT_THROW(io::openSeries(plain.file("case.foam"), {"", "decomposed"}), ConfigError);
    EXPECT_EQ(io::openSeries(plain.file("case.foam"))->load(0).triangleCount(), 12u);
}

// Dynamic-mesh solvers write polyMesh/points into the time directories where the mesh
// moved; a time directory without them keeps the last points written before it. Read with
// 0/ (--foam-zero-time), so the first step is the mesh of constant/; without, 0/ is skipped
// and the case still opens from the first solved time; with 0/ alone, that is the step.
TEST(OpenFoam, MovingMeshPointsAreReadPerStep) {
    ScratchDir dir;
    writeControlDict(dir);
    writeCubeMesh(dir.path(), 0, {{"walls", "wall", {0, 1, 2, 3, 4, 5}}});
    writeField(dir.path() / "0", "U", "volVectorField", "0 1 -1 0 0 0 0", "(0 0 0)", {{"walls", "(0 0 0)"}});
    const core::SurfaceMesh atRest = io::openSeries(dir.file("case.foam"))->load(0);
    ASSERT_NE(atRest.findField("U"), nullptr);
    for (const auto& u : atRest.findField("U")->values) EXPECT_EQ(u, glm::vec3(0)) << "0/ alone: from rest";
    for (const char* t : {"1", "2"})
        writeField(dir.path() / t, "U", "volVectorField", "0 1 -1 0 0 0 0", "(1 0 0)", {{"walls", "(1 0 0)"}});
    fs::create_directories(dir.path() / "1/polyMesh");
    writeText(dir.file("1/polyMesh/points"), header("vectorField", "points") + cubePoints(0, 2));
    auto solved = io::openSeries(dir.file("case.foam"));
    ASSERT_EQ(solved->count(), 2u);
    EXPECT_DOUBLE_EQ(solved->time(0), 1.0);
    EXPECT_FLOAT_EQ(solved->load(0).bounds().lo.z, 2.0f);
    EXPECT_FLOAT_EQ(solved->load(1).bounds().lo.z, 2.0f);
    auto steps = io::openSeries(dir.file("case.foam"), {.patches = {}, .foamCase = "auto", .zeroTime = true});
    ASSERT_EQ(steps->count(), 3u);
    const float expectedLoZ[3] = {0, 2, 2};
    for (size_t i = 0; i < 3; ++i) {
        const core::SurfaceMesh m = steps->load(i);
        EXPECT_EQ(m.triangleCount(), 12u);
        EXPECT_FLOAT_EQ(m.bounds().lo.z, expectedLoZ[i]) << "step " << i;
        EXPECT_FLOAT_EQ(m.bounds().hi.z, expectedLoZ[i] + 1) << "step " << i;
    }
    // Back to the first step: the reader's cached mesh moves back too.
    EXPECT_FLOAT_EQ(steps->load(0).bounds().hi.z, 1.0f);
}

// `dimensions [0 1 -1 0 0 0 0]` is "m/s" (ParaView's notation): on the mesh for the
// legend's title and in `info`; the arrays keep their plain names.
TEST(OpenFoam, UnitsComeFromTheFieldsDimensions) {
    ScratchDir dir;
    writeControlDict(dir);
    writeCubeMesh(dir.path(), 0, {{"walls", "wall", {0, 1, 2, 3, 4, 5}}});
    writeField(dir.path() / "0", "U", "volVectorField", "0 1 -1 0 0 0 0", "(1 0 0)", {{"walls", "(1 0 0)"}});
    writeField(dir.path() / "0", "p", "volScalarField", "0 2 -2 0 0 0 0", "3", {{"walls", "3"}});
    writeField(dir.path() / "0", "T", "volScalarField", "0 0 0 1 0 0 0", "300", {{"walls", "300"}});
    const core::SurfaceMesh m = io::openSeries(dir.file("case.foam"))->load(0);
    ASSERT_NE(m.findField("U"), nullptr);
    ASSERT_NE(m.findScalar("p"), nullptr);
    EXPECT_EQ(m.units.at("U"), "m/s");
    EXPECT_EQ(m.units.at("p"), "m2/s2");
    EXPECT_EQ(m.units.at("T"), "K");
    const io::FileInfo info = io::inspectFile(dir.file("case.foam"));
    for (const auto& a : info.arrays) EXPECT_EQ(a.units, a.name == "U" ? "m/s" : a.name == "p" ? "m2/s2" : "K") << a.name;
}

// `info` says which field is on which patch; a field file without an entry for a patch
// listed before the ones it has makes VTK 9.1 drop it there and after: the user is told.
TEST(OpenFoam, InfoListsPatchesWithTheirFieldsAndMissingEntriesAreWarned) {
    ScratchDir dir;
    writeControlDict(dir);
    writeCubeMesh(dir.path(), 0, {{"walls", "wall", {0, 1, 2, 3}}, {"ends", "patch", {4, 5}}});
    writeField(dir.path() / "0", "U", "volVectorField", "0 1 -1 0 0 0 0", "(1 0 0)", {{"walls", "(1 0 0)"}, {"ends", "(1 0 0)"}});
    writeField(dir.path() / "0", "T", "volScalarField", "0 0 0 1 0 0 0", "0", {{"walls", "2"}});
    // By default the wall-type patch alone is read; info lists both with their types and face counts.
    const io::FileInfo byDefault = io::inspectFile(dir.file("case.foam"));
    ASSERT_EQ(byDefault.parts.size(), 1u);
    EXPECT_EQ(byDefault.parts[0].name, "walls");
    ASSERT_EQ(byDefault.patches.size(), 2u);
    EXPECT_EQ(byDefault.patches[0].name, "walls");
    EXPECT_EQ(byDefault.patches[0].type, "wall");
    EXPECT_EQ(byDefault.patches[0].faces, 4u);
    EXPECT_TRUE(byDefault.patches[0].read);
    EXPECT_EQ(byDefault.patches[1].name, "ends");
    EXPECT_EQ(byDefault.patches[1].type, "patch");
    EXPECT_EQ(byDefault.patches[1].faces, 2u);
    EXPECT_FALSE(byDefault.patches[1].read);
    EXPECT_NE(byDefault.format.find("(wall patches)"), std::string::npos) << byDefault.format;
    // All patches, as asked for.
    io::FileInfo info = io::inspectFile(dir.file("case.foam"), {".*"});
    ASSERT_EQ(info.parts.size(), 2u);
    auto has = [](const io::PartInfo& p, const char* a) {
        return std::find(p.arrays.begin(), p.arrays.end(), a) != p.arrays.end();
    };
    EXPECT_EQ(info.parts[0].name, "walls");
    EXPECT_EQ(info.parts[0].faces, 4u);
    EXPECT_TRUE(has(info.parts[0], "T") && has(info.parts[0], "U"));
    EXPECT_EQ(info.parts[1].name, "ends");
    EXPECT_TRUE(!has(info.parts[1], "T") && has(info.parts[1], "U"));
    EXPECT_NE(io::formatFileInfo(info).find("ends"), std::string::npos);

    // The same with "ends" listed first: T is gone everywhere, and the warning says why.
    writeCubeMesh(dir.path(), 0, {{"ends", "patch", {4, 5}}, {"walls", "wall", {0, 1, 2, 3}}});
    ::testing::internal::CaptureStderr();
    const core::SurfaceMesh m = io::openSeries(dir.file("case.foam"), {".*"})->load(0);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(m.findScalar("T"), nullptr);
    EXPECT_NE(err.find("fields T of time 0 have no entry for boundary patch 'ends'"), std::string::npos) << err;
}

// A case written as OpenFOAM's tutorials are and left by a solver: the fields of 0/ hold
// `#includeEtc "caseDicts/setConstraintTypes"` (VTK 9.1: "Unsupported directive
// includeEtc"), the solved times are plain and have uniform/time. 0/ is skipped by default;
// asked for, it is left out with a warning naming it and the other steps stay; a case with
// that 0/ alone is an error that says why.
TEST(OpenFoam, TutorialCaseOpensAtItsSolvedTimesAndUnparsedTimesAreWarned) {
    ScratchDir dir;
    writeControlDict(dir);
    writeCubeMesh(dir.path(), 0, {{"walls", "wall", {0, 1, 2, 3}}, {"frontAndBack", "empty", {4, 5}}});
    auto writeInitial = [&] {
        fs::create_directories(dir.path() / "0");
        const std::string boundary = "boundaryField\n{\n    #includeEtc \"caseDicts/setConstraintTypes\"\n\n"
                                     "    walls\n    {\n        type noSlip;\n    }\n}\n";
        writeText(dir.file("0/U"), header("volVectorField", "U") +
                                       "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\n" + boundary);
        writeText(dir.file("0/p"), header("volScalarField", "p") +
                                       "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\n" + boundary);
    };
    writeInitial();
    for (const char* t : {"1", "2"}) {
        const std::string u = std::string("(") + t + " 0 0)";
        writeField(dir.path() / t, "U", "volVectorField", "0 1 -1 0 0 0 0", u, {{"walls", u}, {"frontAndBack", u}});
        writeField(dir.path() / t, "p", "volScalarField", "0 2 -2 0 0 0 0", t, {{"walls", t}, {"frontAndBack", t}});
        fs::create_directories(dir.path() / t / "uniform");
        writeText((dir.path() / t / "uniform/time").string(),
                  header("dictionary", "time") + "value " + t + ";\nname \"" + t + "\";\nindex " + t + ";\n");
    }

    // As the solver left it: the solved times, nothing to warn about.
    ::testing::internal::CaptureStderr();
    auto steps = io::openSeries(dir.file("case.foam"));
    ASSERT_EQ(steps->count(), 2u);
    EXPECT_DOUBLE_EQ(steps->time(0), 1.0);
    EXPECT_DOUBLE_EQ(steps->time(1), 2.0);
    const core::SurfaceMesh m = steps->load(1);
    std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(err.find("left out"), std::string::npos) << err;
    ASSERT_NE(m.findField("U"), nullptr);
    for (const auto& u : m.findField("U")->values) EXPECT_EQ(u, glm::vec3(2, 0, 0));
    const io::FileInfo info = io::inspectFile(dir.file("case.foam"));
    EXPECT_NE(info.format.find("initial conditions 0/ skipped"), std::string::npos) << info.format;
    EXPECT_EQ(info.times.size(), 2u);

    // 0/ asked for: VTK cannot parse it, so it is left out by name; the solved times stay.
    ::testing::internal::CaptureStderr();
    auto withZero = io::openSeries(dir.file("case.foam"), {.patches = {}, .foamCase = "auto", .zeroTime = true});
    ASSERT_EQ(withZero->count(), 2u);
    EXPECT_DOUBLE_EQ(withZero->time(0), 1.0);
    EXPECT_NO_THROW(withZero->load(0));
    err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("left out time directory 0: "), std::string::npos) << err;
    EXPECT_NE(err.find("includeEtc"), std::string::npos) << err;

    // Any time directory, not only 0/: one written by hand with a directive VTK lacks.
    writeInitial();
    fs::create_directories(dir.path() / "3");
    fs::copy_file(dir.path() / "0/U", dir.path() / "3/U");
    ::testing::internal::CaptureStderr();
    auto handWritten = io::openSeries(dir.file("case.foam"));
    err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(handWritten->count(), 2u);
    EXPECT_NE(err.find("left out time directory 3: "), std::string::npos) << err;

    // That 0/ alone: nothing VTK can read, and the error says why.
    const fs::path alone = dir.path() / "alone";
    writeControlDict(alone);
    writeCubeMesh(alone, 0, {{"walls", "wall", {0, 1, 2, 3}}, {"frontAndBack", "empty", {4, 5}}});
    fs::create_directories(alone / "0");
    fs::copy_file(dir.path() / "0/U", alone / "0/U");
    try {
        io::openSeries((alone / "case.foam").string());
        ADD_FAILURE() << "a case whose only time VTK cannot parse opened";
    } catch (const FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("time directory 0: "), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Unsupported directive includeEtc"), std::string::npos) << e.what();
    }
}
