// flowsurf viewer tests — what the viewer test files share: the fixture that runs the
// flowsurf program named by $FLOWSURF (headless, or in a real window under Xvfb) and the
// image comparisons of its screenshots with batch renders.
#pragma once

#include "io/image_writer.h"

#include "../common/autocorrelation.h"

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

namespace flowsurf::viewer_test {

namespace fs = std::filesystem;

// xvfb-run on a display number drawn at random: with -a alone, a run right after another
// can take :99 while the earlier Xvfb (killed last by xvfb-run's clean-up, not waited for)
// still holds it.
inline std::string xvfbRun() {
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

inline io::PngImage png(const std::string& p) { return io::readPng(p); }

inline bool isBackground(const io::PngImage& im, size_t i) {
    return im.samples[i * 3] == 255 && im.samples[i * 3 + 1] == 0 && im.samples[i * 3 + 2] == 255;
}

// Fraction of pixels on which both images agree about surface vs background.
inline double maskAgreement(const io::PngImage& a, const io::PngImage& b) {
    size_t n = size_t(a.width) * a.height, same = 0;
    for (size_t i = 0; i < n; ++i) same += isBackground(a, i) == isBackground(b, i);
    return double(same) / double(n);
}

inline size_t surfacePixels(const io::PngImage& a) {
    size_t n = 0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i) n += !isBackground(a, i);
    return n;
}

// Mean absolute difference over all samples, in units of the full range (1 = 255).
inline double meanAbsDiff(const io::PngImage& a, const io::PngImage& b, int x0 = 0, int x1 = -1) {
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
inline double surfaceCorrelation(const io::PngImage& a, const io::PngImage& b) {
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
inline float correlationLength(const io::PngImage& im, int dx, int dy) {
    const auto sample = [&](int x, int y) { return double(im.samples[size_t(y) * im.width + x]); };
    return test::autocorrelationLength(sample, im.width / 4, im.height / 4, 3 * im.width / 4, 3 * im.height / 4, dx, dy,
                                       40, false);
}

inline nlohmann::json readJson(const std::string& p) {
    std::ifstream f(p);
    return nlohmann::json::parse(f);
}

inline glm::vec3 vec3(const nlohmann::json& j) { return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()}; }

}  // namespace flowsurf::viewer_test
