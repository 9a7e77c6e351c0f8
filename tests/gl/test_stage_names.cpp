// The stage names every method's timer reports are rows of methods::kStageNames (the
// benchmark's columns and every report read them from there), on steady and unsteady data
// with every optional stage on.
#include "core/builtin_scenes.h"
#include "methods/stages.h"
#include "session/playback.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace flowsurf;

namespace {

std::set<std::string> timedStages(const std::string& input, const std::string& method) {
    core::DatasetSteps steps(core::makeBuiltin(input));
    session::RenderOptions o;
    o.input = input;
    o.size = {64, 64};
    session::setOption(o, "method", method);
    session::setOption(o, "enhance-contrast", "both");
    session::setOption(o, "edge-mask", "true");
    session::Playback p(o);
    p.open(steps);
    p.setStageTiming(true);
    p.start(false);
    for (int f = 0; f < 3; ++f) p.advance();
    std::set<std::string> names;
    for (const auto& [name, ms] : p.views()[0]->timer().meanMs()) names.insert(name);
    return names;
}

}  // namespace

TEST(StageNames, TableRowsAreDistinct) {
    std::set<std::string> names;
    for (const auto& [stage, name] : methods::kStageNames) EXPECT_TRUE(names.insert(name).second) << name;
    EXPECT_STREQ(methods::stageName(methods::Stage::Overlay), "overlay");
    EXPECT_FALSE(methods::isStageName("noise blend"));
    int exchange = 0;
    for (const auto& [stage, name] : methods::kStageNames) exchange += methods::isExchangeStage(name);
    EXPECT_EQ(exchange, 2);  // the tile exchange and its return; the rest compute
    EXPECT_TRUE(methods::isExchangeStage("tile return"));
}

TEST(StageNames, EveryStageAMethodTimesIsInTheTable) {
    std::set<std::string> seen;
    for (const char* input : {"builtin:sphere:2000", "builtin:double-gyre"})
        for (const char* method : {"isa", "ibfvs", "hybrid"})
            for (const std::string& name : timedStages(input, method)) {
                EXPECT_TRUE(methods::isStageName(name)) << method << " on " << input << " times '" << name << "'";
                // One process exchanges nothing: its every stage is a compute stage.
                EXPECT_FALSE(methods::isExchangeStage(name)) << method << " times '" << name << "'";
                seen.insert(name);
            }
    // The single-process stages all showed up.
    for (const char* name : {"velocity image", "seed textures", "velocity levels", "advection mesh",
                             "texture advection", "particle tracing", "solid noise", "overlay",
                             "contrast (texture)", "contrast (colour)"})
        EXPECT_TRUE(seen.count(name)) << name;
}
