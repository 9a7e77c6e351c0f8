// The viewer as a user drives it: replayed event logs (headless EGL) against batch renders
// of the same options. Runs the flowsurf program named by $FLOWSURF; images are read back
// with io::readPng. The real-window tests are in test_viewer_window.cpp.
#include "viewer_test_util.h"

using namespace flowsurf;
using namespace flowsurf::viewer_test;

// Each method: the replayed session's screenshot shows the surface where the batch
// render does, and its saved config renders offline to the same image (<= 1/255 mean).
TEST_F(Viewer, SavedConfigRendersTheScreenshotOffline) {
    for (const char* method : {"isa", "ibfvs", "hybrid"}) {
        SCOPED_TRACE(method);
        ASSERT_EQ(replay("builtin:tori",
                         std::string("at 0 set method ") + method + "\n"
                         "at 24 screenshot " + path("view.png") + "\n"
                         "at 24 save-config " + path("view.json") + "\n"
                         "at 25 quit\n",
                         "--size 160x120"), 0) << err_;
        ASSERT_EQ(run("render --config '" + path("view.json") + "' -q -o '" + path("batch.png") + "'"), 0) << err_;
        io::PngImage v = png(path("view.png")), b = png(path("batch.png"));
        ASSERT_EQ(v.width, b.width);
        EXPECT_GT(surfacePixels(v), 2000u);
        EXPECT_GE(maskAgreement(v, b), 0.999);
        const double diff = meanAbsDiff(v, b);
        std::printf("%s: mean |viewer - render --config| = %.5f\n", method, diff);
        EXPECT_LE(diff, 1.0 / 255.0);
    }
}

// A left drag turns the camera by the turntable's degrees per pixel (0.25): 80 px ->
// 20 degrees about the up axis; the hybrid's texture stays on the surface (correlation
// with a batch render from the new camera >= 0.9); ISA's texture covers the surface
// exactly where the batch render's does.
TEST_F(Viewer, DragTurnsTheCameraAndTextureStaysOnSurface) {
    for (const char* method : {"hybrid", "isa"}) {
        SCOPED_TRACE(method);
        ASSERT_EQ(replay("builtin:sphere",
                         std::string("at 0 set method ") + method + "\n"
                         "at 1 save-config " + path("before.json") + "\n"
                         "at 5 mouse-move 100 80\n"
                         "at 5 mouse-down left\n"
                         "at 6 mouse-move 140 80\n"
                         "at 7 mouse-move 180 80\n"
                         "at 7 mouse-up left\n"
                         "at 30 screenshot " + path("view.png") + "\n"
                         "at 30 save-config " + path("after.json") + "\n"
                         "at 31 quit\n",
                         "--size 200x160"), 0) << err_;
        nlohmann::json before = readJson(path("before.json")), after = readJson(path("after.json"));
        glm::vec3 t = vec3(after["target"]), e0 = vec3(before["eye"]) - t, e1 = vec3(after["eye"]) - t;
        float turned = glm::degrees(std::atan2(e0.x, e0.z) - std::atan2(e1.x, e1.z));
        EXPECT_NEAR(turned, 80 * 0.25f, 0.01f);
        ASSERT_EQ(run("render --config '" + path("after.json") + "' -q -o '" + path("batch.png") + "'"), 0) << err_;
        io::PngImage v = png(path("view.png")), b = png(path("batch.png"));
        EXPECT_GE(maskAgreement(v, b), 0.999);
        if (std::string(method) == "hybrid") {
            double c = surfaceCorrelation(v, b);
            std::printf("hybrid after drag: correlation with batch render %.4f\n", c);
            EXPECT_GE(c, 0.9);
        }
    }
}

// `m` cycles isa -> ibfvs -> hybrid. ISA and IBFVS advect the same noise along the same
// field, so their pictures differ only in detail; the hybrid's LIC is another picture.
TEST_F(Viewer, MethodSwitchChangesThePicture) {
    ASSERT_EQ(replay("builtin:tori",
                     "at 19 screenshot " + path("isa.png") + "\n"
                     "at 20 key m\n"
                     "at 40 screenshot " + path("ibfvs.png") + "\n"
                     "at 40 save-config " + path("ibfvs.json") + "\n"
                     "at 41 key m\n"
                     "at 61 screenshot " + path("hybrid.png") + "\n"
                     "at 61 save-config " + path("hybrid.json") + "\n"
                     "at 61 quit\n",
                     "--size 160x120 --method isa --overlay gray"), 0) << err_;
    EXPECT_EQ(readJson(path("ibfvs.json"))["method"], "ibfvs");
    EXPECT_EQ(readJson(path("hybrid.json"))["method"], "hybrid");
    io::PngImage isa = png(path("isa.png")), ibfvs = png(path("ibfvs.png")), hybrid = png(path("hybrid.png"));
    const double dIbfvs = meanAbsDiff(isa, ibfvs), cHybrid = surfaceCorrelation(isa, hybrid);
    std::printf("isa -> ibfvs: mean difference %.4f; isa vs hybrid: correlation %.3f\n", dIbfvs, cHybrid);
    EXPECT_GT(dIbfvs, 0.002);
    EXPECT_LT(cHybrid, 0.5);
    EXPECT_GE(maskAgreement(isa, hybrid), 0.999);
}

// builtin:turning-plane: uniform flow along +x at t = 0 turning to +y at t = 8. Played
// to the end (and held there), the texture runs along y, the last step's field.
TEST_F(Viewer, TimeSeriesPlaysToItsEndAndFollowsTheLastField) {
    ASSERT_EQ(replay("builtin:turning-plane",
                     "at 70 flow-texture " + path("end16.png") + "\n"
                     "at 70 save-config " + path("end.json") + "\n"
                     "at 71 quit\n",
                     "--size 160x160 --method isa --time-per-frame 0.25"), 0) << err_;
    nlohmann::json cfg = readJson(path("end.json"));
    EXPECT_EQ(cfg["time"].get<std::string>().substr(cfg["time"].get<std::string>().find(':') + 1), "8");
    io::PngImage f = png(path("end16.png"));
    const float alongY = correlationLength(f, 0, 1), alongX = correlationLength(f, 1, 0);
    std::printf("held at t = 8: correlation length along y %.1f px, along x %.1f px\n", alongY, alongX);
    EXPECT_GT(alongY, 2.0f * alongX);
}

// A bad file (missing, corrupt) or a missing field shows an error; the viewer keeps
// running with the data it had, and still renders it.
TEST_F(Viewer, BadInputShowsAnErrorAndKeepsRunning) {
    {
        std::ofstream g(path("garbage.vtp"));
        for (int i = 0; i < 3000; ++i) g << char((i * 7919) % 251);
    }
    ASSERT_EQ(replay("builtin:sphere",
                     "at 3 open " + path("missing.vtp") + "\n"
                     "at 4 open " + path("garbage.vtp") + "\n"
                     "at 5 set field nosuch\n"
                     "at 6 set alpha 9\n"
                     "at 12 screenshot " + path("after.png") + "\n"
                     "at 12 save-config " + path("after.json") + "\n"
                     "at 13 quit\n",
                     "--size 120x120"), 0) << err_;
    EXPECT_NE(err_.find("missing.vtp"), std::string::npos) << err_;
    EXPECT_NE(err_.find("garbage.vtp"), std::string::npos) << err_;
    EXPECT_NE(err_.find("nosuch"), std::string::npos) << err_;
    EXPECT_NE(err_.find("--alpha"), std::string::npos) << err_;
    EXPECT_GT(surfacePixels(png(path("after.png"))), 3000u);
    nlohmann::json cfg = readJson(path("after.json"));
    EXPECT_EQ(cfg["input"], "builtin:sphere");
    EXPECT_FALSE(cfg.contains("field") && cfg["field"] == "nosuch");
}

TEST_F(Viewer, RecordsVideoAndFrameTimes) {
    ASSERT_EQ(replay("builtin:sphere",
                     "at 2 record " + path("clip.mp4") + "\n"
                     "at 3 save-keyframe " + path("path.json") + "\n"
                     "at 4 key x\n"
                     "at 8 save-keyframe " + path("path.json") + "\n"
                     "at 12 record-stop\n"
                     "at 14 quit\n",
                     "--size 96x96 --stats '" + path("stats.json") + "'"), 0) << err_;
    EXPECT_GT(fs::file_size(path("clip.mp4")), 1000u);
    nlohmann::json stats = readJson(path("stats.json"));
    EXPECT_EQ(stats["frame_ms"].size(), 15u);
    EXPECT_TRUE(stats["stage_ms"].contains("overlay"));
    // Hand-recorded keyframes: a camera path that render accepts.
    nlohmann::json keys = readJson(path("path.json"))["keyframes"];
    ASSERT_EQ(keys.size(), 2u);
    EXPECT_EQ(keys[0]["frame"], 3);
    EXPECT_EQ(keys[1]["frame"], 8);
    EXPECT_NEAR(keys[1]["eye"][0].get<float>() - keys[1]["target"][0].get<float>(), -glm::length(
        vec3(keys[1]["eye"]) - vec3(keys[1]["target"])), 1e-4f);  // along +x: the eye on the -x side
    EXPECT_EQ(run("render builtin:sphere --size 64x64 --frames 8 -q --camera-path '" + path("path.json") + "' -o '" +
                  path("p.png") + "'"), 0) << err_;
}

// A session's recorded events replay to the same pictures.
TEST_F(Viewer, RecordedEventsReplayTheSession) {
    ASSERT_EQ(replay("builtin:tori",
                     "at 0 set method hybrid\n"
                     "at 2 mouse-move 50 50\n"
                     "at 2 mouse-down middle\n"
                     "at 3 mouse-move 70 40\n"
                     "at 3 mouse-up middle\n"
                     "at 4 scroll 1.5\n"
                     "at 5 key t\n"
                     "at 5 mouse-down left\n"
                     "at 6 mouse-move 90 70\n"
                     "at 6 mouse-up left\n"
                     "at 9 screenshot " + path("first.png") + "\n"
                     "at 10 quit\n",
                     "--size 128x96 --record-events '" + path("recorded.log") + "'"), 0) << err_;
    std::ifstream in(path("recorded.log"));
    std::stringstream ss;
    ss << in.rdbuf();
    std::string recorded = ss.str();
    ASSERT_NE(recorded.find("at 6 mouse-move 90 70"), std::string::npos) << recorded;
    fs::rename(path("first.png"), path("original.png"));
    ASSERT_EQ(run("view builtin:tori --headless -q --background '#ff00ff' --size 128x96 --play '" + path("recorded.log") + "'"), 0)
        << err_;
    EXPECT_LE(meanAbsDiff(png(path("original.png")), png(path("first.png"))), 0.0);
}

TEST_F(Viewer, RefusesBadSessionsWithClearErrors) {
    EXPECT_EQ(run("view builtin:sphere --headless"), 2);
    EXPECT_NE(err_.find("--play"), std::string::npos) << err_;
    EXPECT_EQ(run("view builtin:sphere --headless --play '" + path("none.log") + "'"), 3);
    EXPECT_NE(err_.find("none.log"), std::string::npos) << err_;
    std::ofstream(path("bad.log")) << "at 1 key r\nat two key r\n";
    EXPECT_EQ(run("view builtin:sphere --headless --play '" + path("bad.log") + "'"), 4);
    EXPECT_NE(err_.find("bad.log:2"), std::string::npos) << err_;
    EXPECT_EQ(run("view builtin:sphere --headless --compare isa,lic --play '" + path("bad.log") + "'"), 2);
}
