// The dye options [doc/algorithms.md §10]: repeatable --dye with its syntax, the dye file, refusals that
// name the option, and values that read back exactly (config files, event logs).
#include "core/errors.h"
#include "io/text_writer.h"
#include "session/options/dye_sources.h"
#include "cli_options.h"
#include "cli_parse.h"

#include <gtest/gtest.h>

#include <utility>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>

using namespace flowsurf;
using namespace flowsurf::app;

namespace {
RenderOptions parseArgs(std::vector<std::string> args) { return testing_cli::parseRenderArgs(std::move(args)); }

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(DyeOptions, RepeatableSourcesWithRadiusAndColour) {
    RenderOptions o = parseArgs({"builtin:sphere", "--dye", "0,0,1", "--dye", "1,0,0:0.1:blue", "--dye",
                                 "0,1,0::#00ff00", "--dye-release", "5", "--dye-decay", "0.5"});
    ASSERT_EQ(o.dye.size(), 3u);
    EXPECT_EQ(o.dye[0].point, glm::vec3(0, 0, 1));
    EXPECT_EQ(o.dye[0].radius, 0.0f);  // a few pixels
    EXPECT_EQ(o.dye[1].radius, 0.1f);
    EXPECT_EQ(o.dye[1].color, glm::vec3(0.0f, 51.0f / 255.0f, 1.0f));
    EXPECT_EQ(o.dye[2].color, glm::vec3(0, 1, 0));
    EXPECT_NE(o.dye[0].color, o.dye[1].color);  // the palette, not one colour for all
    EXPECT_EQ(o.dyeRelease, 5);
    EXPECT_EQ(o.dyeDecay, 0.5f);
    // The value reads back to the same sources (config files, the viewer's event log).
    RenderOptions back;
    setOption(back, "dye", findOption("dye")->get(o));
    EXPECT_EQ(back.dye, o.dye);
}

// A source made from its values (Renderer::addDye, the viewer's ctrl+click) is the one its
// text reads back as, so a log or a saved state replays it exactly.
TEST(DyeOptions, SourceFromValuesEqualsItsText) {
    const glm::vec3 p(1.0f / 3.0f, -2.7182817f, 0.1f);
    const methods::DyeSource s = dyeSource(p, 0.25f, "orange", 0, "addDye");
    EXPECT_EQ(parseDyeSources(dyeSourcesText({s})).at(0), s);
    EXPECT_EQ(s.point, p);
    // No colour: the palette's, as the text without one gives for the same position.
    const methods::DyeSource third = dyeSource(p, 0.0f, std::nullopt, 2, "addDye");
    EXPECT_EQ(third.color, parseDyeSources("0,0,0;0,0,0;1,1,1").at(2).color);
    EXPECT_NE(messageOf([&] { dyeSource(p, -1.0f, std::nullopt, 0, "addDye"); }).find("addDye"), std::string::npos);
    EXPECT_THROW(dyeSource(glm::vec3(INFINITY, 0, 0), 0.0f, std::nullopt, 0, "addDye"), ConfigError);
    EXPECT_THROW(parseDyeSources("1,2,3:0:"), ConfigError);  // a colour's place with none in it
}

TEST(DyeOptions, BadValuesNameTheOption) {
    RenderOptions o;
    EXPECT_NE(messageOf([&] { setOption(o, "dye", "1,2"); }).find("--dye"), std::string::npos);
    EXPECT_NE(messageOf([&] { setOption(o, "dye", "1,2,3:-1"); }).find("--dye"), std::string::npos);
    EXPECT_NE(messageOf([&] { setOption(o, "dye", "1,2,3:0.1:purplish"); }).find("--dye"), std::string::npos);
    EXPECT_NE(messageOf([&] { setOption(o, "dye-release", "-1"); }).find("--dye-release"), std::string::npos);
    EXPECT_NE(messageOf([&] { setOption(o, "dye-decay", "x"); }).find("--dye-decay"), std::string::npos);
}

TEST(DyeOptions, FileWithStartAndStopFrames) {
    const std::string path = ::testing::TempDir() + "dye_sources.json";
    std::ofstream(path) << R"({"sources": [{"point": [0, 0, 1], "radius": 0.05, "color": "orange", "start": 3,
                                             "stop": 10}, {"point": [1, 0, 0], "color": [0, 0.5, 1]}]})";
    RenderOptions o;
    setOption(o, "dye-file", path);
    ASSERT_EQ(o.dyeFileSources.size(), 2u);
    EXPECT_EQ(o.dyeFileSources[0].start, 3);
    EXPECT_EQ(o.dyeFileSources[0].stop, 10);
    EXPECT_EQ(o.dyeFileSources[0].radius, 0.05f);
    EXPECT_EQ(o.dyeFileSources[1].stop, -1);
    EXPECT_EQ(o.dyeFileSources[1].color, glm::vec3(0, 0.5f, 1));

    std::ofstream(path) << R"([{"point": [0, 0, 1], "start": 5, "stop": 2}])";
    EXPECT_NE(messageOf([&] { setOption(o, "dye-file", path); }).find("source 0"), std::string::npos);
    std::ofstream(path) << R"([{"radius": 1}])";
    EXPECT_NE(messageOf([&] { setOption(o, "dye-file", path); }).find("\"point\""), std::string::npos);
    std::remove(path.c_str());
}
