// --frames N [docs/cfd.md, colour ranges]: a PNG is the image after N frames (frame N); a movie or PNG
// sequence is N frames, 0 .. N-1, and its last frame shows the end of the data-time range.
#include "core/errors.h"
#include "session/animated_surface.h"

#include <gtest/gtest.h>

using namespace flowsurf;

TEST(FrameCount, TimeRangeEndsOnTheLastFrameWritten) {
    session::RenderOptions o;
    o.frames = 12;
    o.output = "x.png";
    EXPECT_DOUBLE_EQ(session::makeTimeMapping(o, {0, 1, 2, 3}).at(12), 3.0);
    for (const char* movie : {"x.mp4", "f_%04d.png"}) {
        o.output = movie;
        const core::TimeMapping m = session::makeTimeMapping(o, {0, 1, 2, 3});
        EXPECT_DOUBLE_EQ(m.at(0), 0.0) << movie;
        EXPECT_DOUBLE_EQ(m.at(11), 3.0) << movie;
    }
    o.output = "";  // no output kind (a front end's): as a PNG
    EXPECT_DOUBLE_EQ(session::makeTimeMapping(o, {0, 1, 2, 3}).at(12), 3.0);
}

TEST(FrameCount, MovieOfNoFramesIsRefused) {
    session::RenderOptions o;
    o.input = "builtin:sphere";
    o.frames = 0;
    o.output = "x.png";
    EXPECT_NO_THROW(session::validateRenderOptions(o));
    o.output = "x.mp4";
    EXPECT_THROW(session::validateRenderOptions(o), ConfigError);
}
