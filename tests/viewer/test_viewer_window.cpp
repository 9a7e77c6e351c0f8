// The viewer in a real GLFW window under Xvfb, its panel and live input, the colour range,
// the quality measurements and dye dropped with the mouse. Runs the flowsurf program named
// by $FLOWSURF.
#include "viewer_test_util.h"

using namespace flowsurf;
using namespace flowsurf::viewer_test;

namespace {

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

}  // namespace

// The real GLFW window under Xvfb: the same session gives the same image as headless,
// and the panel sits beside the image, never over it [doc/contrast.md, the viewer's framing]: the window's
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

// "rescale: visible" [doc/contrast.md, the viewer's framing]: zoomed in on the sphere near a pole of its rotation, the
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

// Collapsing the panel gives its width back [doc/contrast.md, the viewer's framing]: the image then spans the
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

// Dye [doc/algorithms.md §10]: a ctrl + click in the real window drops a source at the surface point
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
