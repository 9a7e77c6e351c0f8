// session::Playback as the owner of a session's options: it exists before any steps are
// open, takes every option then (the input's too), and a playback opened again renders as
// a new one would (flowsurf::Renderer keeps one playback over its surfaces).
#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "session/playback.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

using namespace flowsurf;

namespace {

session::RenderOptions smallOptions() {
    session::RenderOptions o;
    o.input = "builtin:sphere:2000";
    o.size = {64, 48};
    return o;
}

std::vector<uint8_t> image(const session::Playback& p) {
    int w = 0, h = 0;
    return p.readImage(&w, &h);
}

}  // namespace

TEST(PlaybackOptions, ClosedPlaybackTakesEveryOptionAndRendersNothing) {
    session::Playback p(smallOptions());
    EXPECT_FALSE(p.isOpen());
    EXPECT_EQ(p.views().size(), 0u);
    EXPECT_EQ(p.frame(), 0);
    // Closed, the input's options are options like the others.
    EXPECT_EQ(p.set("input", "builtin:torus"), session::OptionEffect::Reload);
    EXPECT_EQ(p.options().input, "builtin:torus");
    EXPECT_EQ(p.set("alpha", "0.25"), session::OptionEffect::Rebuild);
    EXPECT_FLOAT_EQ(p.options().params.common.alpha, 0.25f);
    EXPECT_THROW(p.set("no-such-option", "1"), ConfigError);
    EXPECT_THROW(p.start(true), ConfigError);
    EXPECT_THROW(p.still(0), ConfigError);
    EXPECT_THROW(p.render({}), ConfigError);
}

TEST(PlaybackOptions, OpenRefusesTheInputsOptionsUntilClosed) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:2000"));
    session::Playback p(smallOptions());
    p.open(steps);
    EXPECT_TRUE(p.isOpen());
    EXPECT_EQ(p.views().size(), 1u);
    EXPECT_THROW(p.set("input", "builtin:torus"), ConfigError);
    EXPECT_EQ(p.options().input, "builtin:sphere:2000");
    p.close();
    EXPECT_FALSE(p.isOpen());
    EXPECT_EQ(p.views().size(), 0u);
    EXPECT_NO_THROW(p.set("input", "builtin:sphere:2000"));
}

TEST(PlaybackOptions, ReopenedPlaybackRendersAsANewOne) {
    core::DatasetSteps steps(core::makeBuiltin("builtin:sphere:2000"));
    session::RenderOptions o = smallOptions();
    session::setOption(o, "dye", "0,0,1:0.2:red");
    session::Playback fresh(o);
    fresh.open(steps);
    fresh.still(4);
    const std::vector<uint8_t> expected = image(fresh);

    session::Playback p(o);
    p.setOptions(o);
    p.open(steps);
    p.start(true);
    for (int f = 0; f < 7; ++f) p.advance();  // clock, dye and frame count move on
    p.open(steps);                            // as a new playback: frame 0, clock 0, no dye
    EXPECT_EQ(p.frame(), 0);
    EXPECT_EQ(p.clock(), 0u);
    EXPECT_EQ(p.dye().field(), nullptr);
    p.still(4);
    EXPECT_EQ(image(p), expected);
}

// The viewer's reload: new steps and options in one step; when the new data fails, the
// playback goes on with the data, options, textures and clock it had.
TEST(PlaybackOptions, ReopenKeepsWhatItHadWhenTheNewDataFails) {
    core::DatasetSteps sphere(core::makeBuiltin("builtin:sphere:2000"));
    core::DatasetSteps plane(core::makeBuiltin("builtin:uniform-plane"));
    session::Playback p(smallOptions());
    p.open(sphere);
    p.start(false);
    for (int f = 0; f < 3; ++f) p.advance();
    const std::vector<uint8_t> before = image(p);

    session::RenderOptions bad = smallOptions();
    bad.input = "builtin:uniform-plane";
    bad.field = "no-such-field";
    EXPECT_THROW(p.reopen(plane, bad), Error);
    EXPECT_TRUE(p.isOpen());
    EXPECT_EQ(p.options().input, "builtin:sphere:2000");
    EXPECT_EQ(p.options().field, "");
    EXPECT_EQ(p.frame(), 3);
    EXPECT_EQ(p.clock(), 3u);
    EXPECT_EQ(image(p), before);
    EXPECT_NO_THROW(p.advance());  // and renders on

    session::RenderOptions good = smallOptions();
    good.input = "builtin:uniform-plane";
    p.reopen(plane, good);
    EXPECT_EQ(p.options().input, "builtin:uniform-plane");
    EXPECT_EQ(p.frame(), 0);
    EXPECT_EQ(p.clock(), 0u);
    p.still(2);
    session::Playback fresh(good);
    fresh.open(plane);
    fresh.still(2);
    EXPECT_EQ(image(p), image(fresh));
}
