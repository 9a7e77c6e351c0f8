// Derived fields for bare meshes (curvature directions on a torus, the gradient of a
// linear scalar, a tangential direction), scalars through the readers (a field on one
// OpenFOAM patch only), ParaView colour map files and the --view presets.
#include "core/builtin_scenes.h"
#include "core/derived_fields.h"
#include "core/errors.h"
#include "io/dataset_reader.h"
#include "io/series_reader.h"
#include "session/animated_surface.h"
#include "session/options/colormap_file.h"
#include "session/scene_setup.h"
#include "test_io_common.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>
#include <vtkXMLPolyDataWriter.h>

#include <cmath>
#include <cstdio>

using namespace flowsurf;
using testing_io::ScratchDir;
using testing_io::makeGrid;
using testing_io::writeText;

namespace {
float lineAngleDeg(const glm::vec3& a, const glm::vec3& b) {
    const float c = std::abs(glm::dot(glm::normalize(a), glm::normalize(b)));
    return glm::degrees(std::acos(std::min(c, 1.0f)));
}
}  // namespace

// Torus R = 1, r = 0.35 about y: the larger principal curvature 1/r lies along the tube's
// meridian, d n / d b = -sin(b) ring + cos(b) y, everywhere (|cos b / (R + r cos b)| < 1/r).
TEST(DerivedFields, TorusMaxCurvatureFollowsTheMeridian) {
    core::SurfaceMesh torus = core::makeTorus({0, 0, 0}, 1.0f, 0.35f, 96, 48);
    core::addDerivedField(torus, "curvature-max");
    const core::VectorField* f = torus.findField("curvature-max");
    ASSERT_NE(f, nullptr);
    float worst = 0.0f;
    for (size_t i = 0; i < torus.vertexCount(); ++i) {
        const glm::vec3 p = torus.positions[i];
        const glm::vec3 ring = glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        const glm::vec3 n = torus.normals[i];
        const glm::vec3 meridian = glm::cross(n, glm::cross(ring, glm::vec3(0, 1, 0)));
        worst = std::max(worst, lineAngleDeg(f->values[i], meridian));
    }
    std::printf("worst angle to the meridian %.2f deg\n", worst);
    EXPECT_LT(worst, 10.0f);
    const core::Curvature c = core::principalCurvatures(torus);
    EXPECT_NEAR(c.k1[0], 1.0f / 0.35f, 0.15f / 0.35f);
    // The meridian field is orientable: the spanning tree leaves no edge flipped.
    std::vector<glm::vec3> dirs = c.dir1;
    EXPECT_EQ(core::orientLineField(dirs, torus.triangles), 0u);
}

TEST(DerivedFields, GradientOfALinearScalarOnAPlane) {
    core::SurfaceMesh plane = core::makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0f, 2.0f, 16, 16);
    core::ScalarField s{"p", {}};
    for (const auto& p : plane.positions) s.values.push_back(2.0f * p.x - 3.0f * p.y + 1.0f);
    plane.scalars.push_back(s);
    core::addDerivedField(plane, "gradient:p");
    for (const auto& g : plane.findField("gradient:p")->values) {
        EXPECT_NEAR(g.x, 2.0f, 1e-4f);
        EXPECT_NEAR(g.y, -3.0f, 1e-4f);
        EXPECT_NEAR(g.z, 0.0f, 1e-4f);
    }
    EXPECT_THROW(core::addDerivedField(plane, "gradient:nope"), FieldError);
}

TEST(DerivedFields, DownIsTheTangentialPartOfTheDirection) {
    core::SurfaceMesh plane = core::makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 0.6f, 0.8f}, 1.0f, 1.0f, 4, 4);
    core::addDerivedField(plane, "down:0,-1,0");
    const glm::vec3 n = plane.normals[0];
    for (const auto& v : plane.findField("down:0,-1,0")->values) {
        EXPECT_NEAR(glm::dot(v, n), 0.0f, 1e-5f);
        EXPECT_LT(v.y, 0.0f);
    }
    EXPECT_THROW(core::addDerivedField(plane, "down:0,0"), ConfigError);
}

TEST(Scalars, SpecSelectsComponentsAndMagnitude) {
    core::SurfaceMesh m = core::makeRectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1, 1, 1);
    m.fields.push_back({"U", std::vector<glm::vec3>(m.vertexCount(), glm::vec3(3, 4, 0))});
    std::vector<float> v;
    ASSERT_TRUE(core::evalScalar(m, core::ScalarSpec::parse("U"), v));
    EXPECT_FLOAT_EQ(v[0], 5.0f);
    ASSERT_TRUE(core::evalScalar(m, core::ScalarSpec::parse("U:y"), v));
    EXPECT_FLOAT_EQ(v[0], 4.0f);
    EXPECT_FALSE(core::evalScalar(m, core::ScalarSpec::parse("p"), v));
    EXPECT_THROW(core::ScalarSpec::parse("U:w"), ConfigError);
}

// A hand-written OpenFOAM case: one hex cell, patches "walls" (4 faces) and "ends" (2);
// T is given on "walls" only. It must survive the merge (NaN on "ends"), not vanish.
TEST(Scalars, OpenFoamFieldOnOnePatchIsKept) {
    ScratchDir dir;
    namespace fs = std::filesystem;
    fs::create_directories(dir.path() / "constant/polyMesh");
    fs::create_directories(dir.path() / "0");
    fs::create_directories(dir.path() / "system");
    auto hdr = [](const std::string& cls, const std::string& obj) {
        return "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class " + cls + ";\n    object " + obj + ";\n}\n";
    };
    const std::string mesh = dir.file("constant/polyMesh/");
    writeText(mesh + "points", hdr("vectorField", "points") +
                                   "8\n(\n(0 0 0)\n(1 0 0)\n(1 1 0)\n(0 1 0)\n(0 0 1)\n(1 0 1)\n(1 1 1)\n(0 1 1)\n)\n");
    writeText(mesh + "faces", hdr("faceList", "faces") +
                                  "6\n(\n4(0 4 7 3)\n4(1 2 6 5)\n4(0 1 5 4)\n4(3 7 6 2)\n4(0 3 2 1)\n4(4 5 6 7)\n)\n");
    writeText(mesh + "owner", hdr("labelList", "owner") + "6\n(\n0\n0\n0\n0\n0\n0\n)\n");
    writeText(mesh + "neighbour", hdr("labelList", "neighbour") + "0\n(\n)\n");
    writeText(mesh + "boundary", hdr("polyBoundaryMesh", "boundary") +
                                     "2\n(\nwalls\n{\n type wall;\n nFaces 4;\n startFace 0;\n}\n"
                                     "ends\n{\n type patch;\n nFaces 2;\n startFace 4;\n}\n)\n");
    writeText(dir.file("0/T"), hdr("volScalarField", "T") +
                                   "dimensions [0 0 0 1 0 0 0];\ninternalField uniform 0;\nboundaryField\n{\n"
                                   " walls\n {\n type fixedValue;\n value uniform 2;\n }\n}\n");
    writeText(dir.file("0/U"), hdr("volVectorField", "U") +
                                   "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField\n{\n"
                                   " walls\n {\n type fixedValue;\n value uniform (1 0 0);\n }\n"
                                   " ends\n {\n type fixedValue;\n value uniform (1 0 0);\n }\n}\n");
    writeText(dir.file("system/controlDict"), hdr("dictionary", "controlDict") +
                                                  "application icoFoam;\nstartTime 0;\nendTime 1;\ndeltaT 1;\n");
    writeText(dir.file("case.foam"), "");
    // Every patch (by default only the wall patch is read, which has T throughout).
    const core::SurfaceMesh m = io::openSeries(dir.file("case.foam"), {".*"})->load(0);
    EXPECT_EQ(m.triangleCount(), 12u);
    const core::ScalarField* t = m.findScalar("T");
    ASSERT_NE(t, nullptr) << "T was dropped";
    size_t two = 0, nan = 0;
    for (float v : t->values) (std::isnan(v) ? nan : two) += std::isnan(v) || v == 2.0f ? 1 : 0;
    EXPECT_GT(two, 0u);
    EXPECT_GT(nan, 0u);
    EXPECT_NE(m.findField("U"), nullptr);
    // --patches selects boundary patches by name, and the default is the wall-type patch:
    // the four wall faces only, T everywhere.
    for (const char* patches : {"wal.*", ""}) {
        core::SurfaceMesh walls = io::openSeries(dir.file("case.foam"), {patches})->load(0);
        EXPECT_EQ(walls.triangleCount(), 8u) << "--patches '" << patches << "'";
        ASSERT_NE(walls.findScalar("T"), nullptr);
        for (float v : walls.findScalar("T")->values) EXPECT_EQ(v, 2.0f);
    }
    EXPECT_THROW(io::openSeries(dir.file("case.foam"), {"nope"}), ConfigError);
}

// A cell scalar with no value (NaN) on one cell: the points it shares with a cell that has
// a value take that value; only the points of NaN cells alone stay NaN (VTK's averaging
// would make every point of the NaN cell NaN, shrinking the coloured part by a ring).
TEST(Scalars, NanCellsDoNotSpreadToSharedPoints) {
    ScratchDir dir;
    vtkSmartPointer<vtkPolyData> grid = makeGrid(2, 1);  // two quads sharing the edge x = 1
    grid->GetCellData()->GetArray("cellId")->SetTuple1(0, 5.0);
    grid->GetCellData()->GetArray("cellId")->SetTuple1(1, std::nan(""));
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(grid);
    writer->SetFileName(dir.file("half.vtp").c_str());
    ASSERT_EQ(writer->Write(), 1);
    const core::SurfaceMesh m = io::readDataset(dir.file("half.vtp")).steps.at(0).mesh;
    const core::ScalarField* s = m.findScalar("cellId");
    ASSERT_NE(s, nullptr);
    for (size_t i = 0; i < m.vertexCount(); ++i) {
        if (m.positions[i].x < 1.5f) EXPECT_EQ(s->values[i], 5.0f) << "point at x = " << m.positions[i].x;
        else EXPECT_TRUE(std::isnan(s->values[i])) << "point at x = " << m.positions[i].x;
    }
}

// The legend's title carries the colour array's units when the file gives them; --title wins.
TEST(Scalars, LegendTitleGainsTheUnits) {
    const std::map<std::string, std::string> units{{"U", "m/s"}, {"p", "m2/s2"}};
    methods::MethodParams params;
    EXPECT_EQ(session::withUnitsInTitle(params, "U", units).common.title, "|U| [m/s]");
    params.common.colorBy = "p";
    EXPECT_EQ(session::withUnitsInTitle(params, "U", units).common.title, "p [m2/s2]");
    params.common.colorBy = "U:x";
    EXPECT_EQ(session::withUnitsInTitle(params, "U", units).common.title, "U:x [m/s]");
    params.common.colorBy = "T";  // no units known: the method's default title (the name)
    EXPECT_EQ(session::withUnitsInTitle(params, "U", units).common.title, "");
    params.common.title = "pressure";
    EXPECT_EQ(session::withUnitsInTitle(params, "U", units).common.title, "pressure");
}

TEST(Colormaps, ParaViewJsonPresetIsSampled) {
    ScratchDir dir;
    writeText(dir.file("map.json"),
              R"([{"Name": "test", "ColorSpace": "RGB", "RGBPoints": [-1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 1, 1]}])");
    std::vector<glm::vec3> t = session::readParaViewColormap(dir.file("map.json"));
    ASSERT_EQ(t.size(), 256u);
    EXPECT_NEAR(t.front().r, 0.0f, 1e-6f);
    EXPECT_NEAR(t[128].r, 1.0f, 0.01f);
    EXPECT_NEAR(t.back().b, 1.0f, 1e-6f);
    writeText(dir.file("bad.json"), R"({"Name": "x"})");
    EXPECT_THROW(session::readParaViewColormap(dir.file("bad.json")), ConfigError);
}

// ParaView's buttons: "+x" looks along +x (the -x side faces the camera); iso from the
// +right/+up/+front octant; the up vector is the --up-axis.
TEST(ViewPresets, ExpectedAxisFacesTheCamera) {
    core::Bounds b;
    b.extend(glm::vec3(-1));
    b.extend(glm::vec3(1));
    session::RenderOptions o;
    const std::pair<const char*, glm::vec3> cases[] = {{"+x", {-1, 0, 0}}, {"-x", {1, 0, 0}}, {"+y", {0, -1, 0}},
                                                       {"-y", {0, 1, 0}},  {"+z", {0, 0, -1}}, {"-z", {0, 0, 1}}};
    for (int up = 0; up < 3; ++up)
        for (const auto& [view, toward] : cases) {
            session::setOption(o, "view", view);
            o.upAxis = up;
            const core::Camera c = session::makeCamera(o, b);
            EXPECT_GT(glm::dot(glm::normalize(c.eye - c.target), toward), 0.999f) << view << " up " << up;
            EXPECT_LT(std::abs(glm::dot(glm::normalize(c.up), glm::normalize(c.eye - c.target))), 1e-3f);
        }
    session::setOption(o, "view", "iso");
    o.upAxis = 2;
    const core::Camera iso = session::makeCamera(o, b);
    EXPECT_GT(glm::dot(iso.up, glm::vec3(0, 0, 1)), 0.99f);
    EXPECT_GT((iso.eye - iso.target).z, 0.0f);
    // z-up default view: from the front (-y), a little above (+z).
    session::setOption(o, "view", "");
    const core::Camera def = session::makeCamera(o, b);
    EXPECT_LT((def.eye - def.target).y, 0.0f);
    EXPECT_GT((def.eye - def.target).z, 0.0f);
}
