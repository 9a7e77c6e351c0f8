// session::Playback before any data is open (the viewer's state holds one from its start):
// a reopen whose data fails leaves it closed with the options it had. Without GL: the
// field is checked before anything is uploaded.
#include "core/builtin_scenes.h"
#include "core/errors.h"
#include "session/playback.h"

#include <gtest/gtest.h>

using namespace flowsurf;

TEST(PlaybackClosed, FailedReopenKeepsItClosedWithItsOptions) {
    session::RenderOptions o;
    o.input = "builtin:sphere:2000";
    session::setOption(o, "alpha", "0.25");
    session::Playback p(o);
    core::DatasetSteps plane(core::makeBuiltin("builtin:uniform-plane"));
    session::RenderOptions bad = o;
    bad.input = "builtin:uniform-plane";
    bad.field = "no-such-field";
    try {
        p.reopen(plane, bad);
        FAIL() << "a field the data does not have was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no-such-field"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(p.isOpen());
    EXPECT_EQ(p.options().input, "builtin:sphere:2000");
    EXPECT_EQ(p.options().field, "");
    EXPECT_FLOAT_EQ(p.options().params.common.alpha, 0.25f);
}
