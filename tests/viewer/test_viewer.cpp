// The viewer as a user drives it: replayed event logs (headless EGL, and one in a real
// GLFW window under Xvfb) against batch renders of the same options. Runs the flowsurf
// program named by $FLOWSURF; images are read back with io::readPng.
#include "io/image_writer.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

using namespace flowsurf;
namespace fs = std::filesystem;

namespace {

// xvfb-run on a display number drawn at random: with -a alone, a run right after another
// can take :99 while the earlier Xvfb (killed last by xvfb-run's clean-up, not waited for)
// still holds it.
std::string xvfbRun() {
    return "xvfb-run -a -n " + std::to_string(200 + std::random_device{}() % 600) + " -s '-screen 0 1024x768x24' ";
}

// Background of every test render: a colour no texture makes, so it marks "no surface".
constexpr const char* kBackground = "#ff00ff";

class Viewer : public ::testing::Test {
protected:
    void SetUp() override {
        const char* exe = std::getenv("FLOWSURF");
        ASSERT_NE(exe, nullptr) << "set FLOWSURF to the flowsurf program";
        exe_ = exe;
        char tmpl[] = "/tmp/flowsurf_viewer_XXXXXX";
        ASSERT_NE(mkdtemp(tmpl), nullptr);
        dir_ = tmpl;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return dir_ + "/" + name; }

    // Runs `flowsurf ARGS`; stderr lands in err_.
    int run(const std::string& args, const std::string& prefix = "") {
        const std::string errFile = path("stderr.txt");
        const std::string cmd = prefix + "'" + exe_ + "' " + args + " 2> '" + errFile + "' > /dev/null";
        int rc = std::system(cmd.c_str());
        std::ifstream f(errFile);
        std::stringstream ss;
        ss << f.rdbuf();
        err_ = ss.str();
        return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    }
    // Runs tests/viewer/SCRIPT under Xvfb against the real window (xdotool input); its exit
    // status. The caller skips when hasWindowTools() is false.
    static bool hasWindowTools() {
        return std::system("command -v xvfb-run > /dev/null && command -v xdotool > /dev/null") == 0;
    }
    int runWindowScript(const std::string& script) {
        const std::string file = std::string(FLOWSURF_SOURCE_DIR) + "/tests/viewer/" + script;
        return std::system((xvfbRun() + "'" + file + "' '" + exe_ + "' '" + dir_ + "'").c_str());
    }
    // Writes an event log and replays it headless on `input` with `options`.
    int replay(const std::string& input, const std::string& log, const std::string& options,
               const std::string& prefix = "", bool headless = true) {
        std::ofstream(path("session.log")) << "# flowsurf events 1\n" << log;
        return run("view " + input + " --play '" + path("session.log") + "' " + (headless ? "--headless " : "") +
                       "-q --background '" + kBackground + "' " + options,
                   prefix);
    }

    std::string exe_, dir_, err_;
};

io::PngImage png(const std::string& p) { return io::readPng(p); }

bool isBackground(const io::PngImage& im, size_t i) {
    return im.samples[i * 3] == 255 && im.samples[i * 3 + 1] == 0 && im.samples[i * 3 + 2] == 255;
}

// Fraction of pixels on which both images agree about surface vs background.
double maskAgreement(const io::PngImage& a, const io::PngImage& b) {
    size_t n = size_t(a.width) * a.height, same = 0;
    for (size_t i = 0; i < n; ++i) same += isBackground(a, i) == isBackground(b, i);
    return double(same) / double(n);
}

size_t surfacePixels(const io::PngImage& a) {
    size_t n = 0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i) n += !isBackground(a, i);
    return n;
}

// Mean absolute difference over all samples, in units of the full range (1 = 255).
double meanAbsDiff(const io::PngImage& a, const io::PngImage& b, int x0 = 0, int x1 = -1) {
    if (x1 < 0) x1 = a.width;
    double sum = 0;
    size_t n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                size_t i = (size_t(y) * a.width + x) * 3 + c;
                sum += std::abs(double(a.samples[i]) - double(b.samples[i]));
                ++n;
            }
    return sum / double(n) / 255.0;
}

// Pearson correlation of luminance over pixels that are surface in both.
double surfaceCorrelation(const io::PngImage& a, const io::PngImage& b) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    size_t n = 0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i) {
        if (isBackground(a, i) || isBackground(b, i)) continue;
        double la = a.samples[i * 3] + a.samples[i * 3 + 1] + a.samples[i * 3 + 2];
        double lb = b.samples[i * 3] + b.samples[i * 3 + 1] + b.samples[i * 3 + 2];
        sa += la, sb += lb, saa += la * la, sbb += lb * lb, sab += la * lb, ++n;
    }
    double cov = sab / n - sa / n * sb / n, va = saa / n - sa / n * sa / n, vb = sbb / n - sb / n * sb / n;
    return cov / std::sqrt(va * vb);
}

// Lag (pixels) where the autocorrelation of a 16-bit gray image along (dx, dy) drops
// below 0.5, over the central half of the image.
float correlationLength(const io::PngImage& im, int dx, int dy) {
    const int x0 = im.width / 4, x1 = 3 * im.width / 4, y0 = im.height / 4, y1 = 3 * im.height / 4;
    double mean = 0, var = 0;
    int n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) mean += im.samples[size_t(y) * im.width + x], ++n;
    mean /= n;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            double d = im.samples[size_t(y) * im.width + x] - mean;
            var += d * d;
        }
    var /= n;
    double prev = 1.0;
    for (int lag = 1; lag < 40; ++lag) {
        double c = 0;
        int m = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                c += (im.samples[size_t(y) * im.width + x] - mean) *
                     (im.samples[size_t(y + lag * dy) * im.width + x + lag * dx] - mean);
                ++m;
            }
        c /= m * var;
        if (c < 0.5) return float(lag - 1) + float((prev - 0.5) / (prev - c));
        prev = c;
    }
    return 40.0f;
}

nlohmann::json readJson(const std::string& p) {
    std::ifstream f(p);
    return nlohmann::json::parse(f);
}

glm::vec3 vec3(const nlohmann::json& j) { return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()}; }

}  // namespace

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

// The columns [x0, x0 + width) of `im`.
io::PngImage columns(const io::PngImage& im, int x0, int width) {
    io::PngImage out = im;
    out.width = width;
    out.samples.clear();
    for (int y = 0; y < im.height; ++y)
        for (int x = x0; x < x0 + width; ++x)
            for (int c = 0; c < 3; ++c) out.samples.push_back(im.samples[(size_t(y) * im.width + x) * 3 + c]);
    return out;
}

// The real GLFW window under Xvfb: the same session gives the same image as headless,
// and the panel sits beside the image, never over it [issue 28 item 4]: the window's
// right part is the image, exactly.
TEST_F(Viewer, RealWindowUnderXvfb) {
    if (std::system("command -v xvfb-run > /dev/null") != 0) GTEST_SKIP() << "xvfb-run is not installed";
    const std::string log = "at 0 set method isa\n"
                            "at 3 mouse-move 100 60\n"
                            "at 3 mouse-down left\n"
                            "at 4 mouse-move 130 70\n"
                            "at 4 mouse-up left\n"
                            "at 20 screenshot " + path("shot.png") + "\n"
                            "at 20 window-screenshot " + path("window.png") + "\n"
                            "at 21 quit\n";
    ASSERT_EQ(replay("builtin:tori", log, "--size 480x360", xvfbRun(), false), 0)
        << err_;
    fs::rename(path("shot.png"), path("window_shot.png"));
    fs::rename(path("window.png"), path("window_full.png"));
    ASSERT_EQ(replay("builtin:tori", log, "--size 480x360"), 0) << err_;
    io::PngImage w = png(path("window_shot.png")), h = png(path("shot.png")), full = png(path("window_full.png"));
    ASSERT_EQ(w.width, 480);
    EXPECT_LE(meanAbsDiff(w, h), 1.0 / 255.0);
    // The panel at the left, beside the image: the window is wider by it, and its right
    // part is the image.
    const int panel = full.width - w.width;
    EXPECT_GE(panel, 300);
    EXPECT_GT(meanAbsDiff(columns(full, 0, 60), columns(w, 0, 60)), 0.05);
    EXPECT_LE(meanAbsDiff(columns(full, panel, w.width), w), 1.0 / 255.0);
}

// "rescale: visible" [issue 28]: zoomed in on the sphere near a pole of its rotation, the
// colour range becomes the speeds the view shows (0 .. 1 on the whole sphere), set and
// recorded as MIN:MAX so that the log replays it without the view.
TEST_F(Viewer, ColorRangeVisibleRescalesToTheShownValues) {
    ASSERT_EQ(replay("builtin:sphere",
                     "at 2 mouse-move 140 50\n"
                     "at 3 scroll 6\n"
                     "at 7 set color-range visible\n"
                     "at 12 save-config " + path("visible.json") + "\n"
                     "at 13 quit\n",
                     "--size 240x200 --record-events '" + path("visible.log") + "'"), 0) << err_;
    const std::string range = readJson(path("visible.json"))["color-range"].get<std::string>();
    float lo = 0, hi = 0;
    ASSERT_EQ(std::sscanf(range.c_str(), "%f:%f", &lo, &hi), 2) << range;
    EXPECT_GE(lo, 0.0f);
    EXPECT_LT(hi, 0.95f) << "the fastest speeds (the equator) are out of view";
    EXPECT_GT(hi - lo, 0.3f);
    std::ifstream in(path("visible.log"));
    std::stringstream log;
    log << in.rdbuf();
    EXPECT_NE(log.str().find("set color-range " + range), std::string::npos) << log.str();
    // An empty view has no range: an error, and the range stays.
    ASSERT_EQ(replay("builtin:sphere", "at 2 set eye 0,0,-40\nat 2 set target 0,0,-50\nat 3 set color-range visible\n"
                     "at 4 save-config " + path("none.json") + "\nat 5 quit\n", "--size 96x96"), 0) << err_;
    EXPECT_NE(err_.find("color-range visible"), std::string::npos) << err_;
    EXPECT_EQ(readJson(path("none.json"))["color-range"].get<std::string>(), "robust");
}

// Collapsing the panel gives its width back [issue 28 item 4]: the image then spans the
// window (the same window, one view as wide as the window), the camera fitted again to
// it; shown again, the image is as wide as before.
TEST_F(Viewer, CollapsedPanelGivesTheSpaceBack) {
    if (std::system("command -v xvfb-run > /dev/null") != 0) GTEST_SKIP() << "xvfb-run is not installed";
    const std::string log = "at 5 window-screenshot " + path("open.png") + "\n"
                            "at 5 screenshot " + path("open_shot.png") + "\n"
                            "at 6 set panel-collapsed true\n"
                            "at 12 window-screenshot " + path("collapsed.png") + "\n"
                            "at 12 screenshot " + path("collapsed_shot.png") + "\n"
                            "at 13 set panel-collapsed false\n"
                            "at 19 screenshot " + path("again_shot.png") + "\n"
                            "at 20 quit\n";
    ASSERT_EQ(replay("builtin:tori", log, "--size 480x360", xvfbRun(), false), 0)
        << err_;
    const io::PngImage open = png(path("open.png")), openShot = png(path("open_shot.png"));
    const io::PngImage collapsed = png(path("collapsed.png")), shot = png(path("collapsed_shot.png"));
    EXPECT_EQ(openShot.width, 480);
    EXPECT_EQ(collapsed.width, open.width);
    EXPECT_EQ(shot.width, collapsed.width) << "the collapsed panel's width goes to the view";
    EXPECT_EQ(png(path("again_shot.png")).width, 480);
    // The fitted camera follows the wider view: the surface is as tall as before, centred.
    size_t left = 0, right = 0;
    for (int y = 0; y < shot.height; ++y)
        for (int x = 0; x < shot.width; ++x)
            (x < shot.width / 2 ? left : right) += !isBackground(shot, size_t(y) * shot.width + x);
    EXPECT_GT(left, 0u);
    EXPECT_NEAR(double(left) / double(left + right), 0.5, 0.15);
}

// Real mouse and keyboard events (xdotool) into the real window: GLFW's callbacks turn
// them into the same events a log holds; the recorded session replays to the same image.
TEST_F(Viewer, LiveInputInTheRealWindowReplaysExactly) {
    if (!hasWindowTools()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
    ASSERT_EQ(runWindowScript("live_input.sh"), 0);
    std::ifstream in(path("live.log"));
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string log = ss.str();
    EXPECT_NE(log.find("mouse-down left"), std::string::npos) << log;
    EXPECT_NE(log.find("mouse-up left"), std::string::npos) << log;
    EXPECT_NE(log.find("key m"), std::string::npos) << log;
    EXPECT_NE(log.find("key p"), std::string::npos) << log;
    EXPECT_GT(std::count(log.begin(), log.end(), '\n'), 8);  // mouse moves were recorded
    fs::rename(path("live.png"), path("live_window.png"));
    ASSERT_EQ(run("view builtin:tori --size 640x480 --headless -q -o '" + path("live.png") + "' --play '" +
                  path("live.log") + "'"), 0) << err_;
    EXPECT_LE(meanAbsDiff(png(path("live_window.png")), png(path("live.png"))), 0.0);
}

// The panel's Quality section is the event `set quality N|off`: off by default, measured
// every N frames when on, summarised per view in --stats; a bad value is reported and the
// viewer goes on.
TEST_F(Viewer, QualityMeasuredEveryNFramesWhenOn) {
    ASSERT_EQ(replay("builtin:sphere",
                     "at 0 set compare isa,hybrid\n"
                     "at 1 set quality 0\n"
                     "at 2 set quality 3\n"
                     "at 14 quit\n",
                     "--size 96x96 --stats '" + path("stats.json") + "'"), 0) << err_;
    EXPECT_NE(err_.find("quality: '0'"), std::string::npos) << err_;
    nlohmann::json stats = readJson(path("stats.json"));
    ASSERT_TRUE(stats.contains("quality"));
    for (const char* m : {"isa", "hybrid"}) {
        EXPECT_GE(stats["quality"][m]["frames"].get<int>(), 3) << m;
        EXPECT_LT(stats["quality"][m]["median"]["orientation_error_deg"].get<double>(), 15.0) << m;
    }
    ASSERT_EQ(replay("builtin:sphere", "at 5 quit\n", "--size 96x96 --stats '" + path("off.json") + "'"), 0) << err_;
    EXPECT_FALSE(readJson(path("off.json")).contains("quality"));
}

// Dye [issue 20]: a ctrl + click in the real window drops a source at the surface point
// under the cursor (on the unit sphere), recorded as a `set dye` event; the replayed
// session shows the ink on the surface only, and none before the event.
TEST_F(Viewer, CtrlClickDropsDyeOnTheSurfaceAndReplays) {
    if (!hasWindowTools()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
    ASSERT_EQ(runWindowScript("dye_click.sh"), 0);
    std::ifstream in(path("dye.log"));
    std::string line, dyeValue;
    while (std::getline(in, line))
        if (auto at = line.find(" set dye "); at != std::string::npos) dyeValue = line.substr(at + 9);
    ASSERT_FALSE(dyeValue.empty()) << "no `set dye` event recorded";
    glm::vec3 p(0.0f);
    ASSERT_EQ(std::sscanf(dyeValue.c_str(), "%f,%f,%f", &p.x, &p.y, &p.z), 3) << dyeValue;
    EXPECT_NEAR(glm::length(p), 1.0f, 0.01f) << "the point under the cursor, on the unit sphere";
    EXPECT_GT(p.z, 0.0f) << "on the side facing the camera";

    // Replayed: red ink where the sphere is, none on the background, none before.
    ASSERT_EQ(replay("builtin:sphere",
                     "at 2 screenshot " + path("before.png") + "\n"
                     "at 3 set dye " + dyeValue.substr(0, dyeValue.find(':')) + ":0.15:red\n"
                     "at 20 screenshot " + path("after.png") + "\n"
                     "at 21 quit\n",
                     "--size 200x160 --overlay gray --lighting off"), 0) << err_;
    auto red = [](const io::PngImage& im) {
        size_t n = 0;
        for (size_t i = 0; i < size_t(im.width) * im.height; ++i)
            n += !isBackground(im, i) && im.samples[i * 3] > 200 && im.samples[i * 3 + 1] < 60;
        return n;
    };
    EXPECT_EQ(red(png(path("before.png"))), 0u);
    EXPECT_GT(red(png(path("after.png"))), 30u);
}
