// The viewer's logic without a window: event logs, and what events do to the state
// (camera by the stated degrees per pixel, method switches, time playback, errors).
#include "session/animated_surface.h"
#include "core/errors.h"
#include "view_events.h"
#include "view_state.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>

#include <cmath>

using namespace flowsurf;
using namespace flowsurf::app;
using namespace flowsurf::app::view;

namespace {

core::Bounds unitBox() {
    core::Bounds b;
    b.extend(glm::vec3(-1.0f));
    b.extend(glm::vec3(1.0f));
    return b;
}

ViewerState loaded(RenderOptions o = {}, std::vector<double> times = {}, double perFrame = 0.0) {
    o.input = "builtin:sphere";
    o.size = {400, 300};
    ViewerState s(o);
    core::TimeMapping m;
    if (!times.empty()) m = {o.timeRange ? o.timeRange->first : times.front(),
                             o.timeRange ? o.timeRange->second : times.back(), perFrame};
    s.dataLoaded(unitBox(), times, m);
    return s;
}

void drag(ViewerState& s, const char* button, glm::vec2 from, glm::vec2 to, bool shift = false) {
    Event e{0, EventType::MouseMove};
    e.x = from.x, e.y = from.y;
    s.handle(e);
    Event down{0, EventType::MouseDown, button};
    down.shift = shift;
    s.handle(down);
    e.x = to.x, e.y = to.y;
    s.handle(e);
    s.handle({0, EventType::MouseUp, button});
}

// Angle of v about the y axis (azimuth), degrees.
float azimuthDeg(const glm::vec3& v) { return glm::degrees(std::atan2(v.x, v.z)); }

}  // namespace

TEST(ViewEvents, ParsesTheDocumentedLog) {
    const std::string log =
        "# flowsurf events 1\n"
        "at 0 set method hybrid            # any render option\n"
        "at 10 mouse-move 400 300\n"
        "at 10 mouse-down left\n"
        "at 25 mouse-move 520 300\n"
        "at 25 mouse-up left\n"
        "at 30 scroll -2\n"
        "at 31 key r\n"
        "at 90 screenshot out/a.png\n"
        "at 90 flow-texture out/a16.png\n"
        "at 90 save-config out/a.json\n"
        "at 91 quit\n";
    std::vector<Event> e = parseEventLog(log, "t.log");
    ASSERT_EQ(e.size(), 11u);
    EXPECT_EQ(e[0].type, EventType::Set);
    EXPECT_EQ(e[0].name, "method");
    EXPECT_EQ(e[0].value, "hybrid");
    EXPECT_EQ(e[1].frame, 10);
    EXPECT_FLOAT_EQ(e[3].x, 520.0f);
    EXPECT_FLOAT_EQ(e[5].x, -2.0f);
    EXPECT_EQ(e[6].name, "r");
    EXPECT_EQ(e[7].value, "out/a.png");
    EXPECT_EQ(e[10].type, EventType::Quit);
    // Formatting and parsing again gives the same events.
    std::vector<Event> again = parseEventLog(formatEventLog(e), "again");
    ASSERT_EQ(again.size(), e.size());
    for (size_t i = 0; i < e.size(); ++i) EXPECT_EQ(formatEvent(again[i]), formatEvent(e[i]));
}

TEST(ViewEvents, BadLinesNameFileAndLine) {
    auto message = [](const std::string& text) {
        try {
            parseEventLog(text, "s.log");
        } catch (const FormatError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message("at 1 key r\nat x key r\n").find("s.log:2"), std::string::npos);
    EXPECT_NE(message("at 1 jump 3\n").find("unknown event 'jump'"), std::string::npos);
    EXPECT_NE(message("at 1 mouse-move 3\n").find("s.log:1"), std::string::npos);
    EXPECT_NE(message("at 1 mouse-down thumb\n").find("thumb"), std::string::npos);
    EXPECT_NE(message("at -3 quit\n").find("non-negative"), std::string::npos);
    EXPECT_NE(message("at 2 screenshot\n").find("needs a FILE"), std::string::npos);
    EXPECT_NE(message("key r\n").find("expected 'at FRAME"), std::string::npos);
    // Out of order frames are sorted, same-frame order kept.
    std::vector<Event> e = parseEventLog("at 5 key r\nat 1 key m\nat 1 key c\n", "o.log");
    EXPECT_EQ(e[0].name, "m");
    EXPECT_EQ(e[1].name, "c");
    EXPECT_EQ(e[2].name, "r");
}

// Turntable: a horizontal drag of d pixels turns the eye about the up axis by
// d * kDegPerPixel degrees, keeping its distance; a vertical drag changes the elevation.
TEST(ViewState, TurntableDragTurnsByStatedDegreesPerPixel) {
    ViewerState s = loaded();
    const glm::vec3 eye0 = *s.options().eye, target = *s.options().target;
    drag(s, "left", {200, 150}, {320, 150});
    const glm::vec3 eye1 = *s.options().eye;
    float turned = azimuthDeg(eye0 - target) - azimuthDeg(eye1 - target);
    EXPECT_NEAR(turned, 120.0f * kDegPerPixel, 0.01f);
    EXPECT_NEAR(glm::length(eye1 - target), glm::length(eye0 - target), 1e-4f);
    EXPECT_NEAR(eye1.y, eye0.y, 1e-4f);  // same elevation
    // Dragging down raises the camera; the elevation stops short of the pole.
    drag(s, "left", {200, 150}, {200, 2000});
    const glm::vec3 up = glm::normalize(*s.options().eye - target);
    EXPECT_GT(up.y, std::cos(glm::radians(1.5f)));
    EXPECT_LT(up.y, 1.0f);
}

TEST(ViewState, PanZoomAndViewKeys) {
    ViewerState s = loaded();
    const glm::vec3 eye0 = *s.options().eye, t0 = *s.options().target;
    drag(s, "left", {200, 150}, {240, 150}, /*shift=*/true);  // pan
    EXPECT_NEAR(glm::length(*s.options().eye - *s.options().target), glm::length(eye0 - t0), 1e-4f);
    EXPECT_GT(glm::length(*s.options().target - t0), 0.01f);
    s.handle({0, EventType::Key, "r"});
    EXPECT_NEAR(glm::length(*s.options().target - t0), 0.0f, 1e-5f);
    // Zoom at the centre of the view: towards the target by the stated factor per step.
    Event at{0, EventType::MouseMove};
    at.x = 199.5f, at.y = 149.5f;
    s.handle(at);
    Event wheel{0, EventType::Scroll};
    wheel.x = 2;
    s.handle(wheel);
    EXPECT_NEAR(glm::length(*s.options().eye - *s.options().target), glm::length(eye0 - t0) * kZoomPerStep * kZoomPerStep,
                1e-3f);
    s.handle({0, EventType::Key, "x"});  // view direction +x: the eye on the -x side
    glm::vec3 dir = glm::normalize(*s.options().target - *s.options().eye);
    EXPECT_NEAR(dir.x, 1.0f, 1e-5f);
    s.handle({0, EventType::Key, "Y"});  // along -y: up must not be parallel
    dir = glm::normalize(*s.options().target - *s.options().eye);
    EXPECT_NEAR(dir.y, -1.0f, 1e-5f);
    EXPECT_LT(std::abs(glm::dot(*s.options().up, dir)), 0.01f);
}

TEST(ViewState, OptionsAndKeysRequestWhatTheyChange) {
    ViewerState s = loaded();
    s.handle({0, EventType::Key, "m"});
    EXPECT_EQ(s.options().method, methods::Method::Ibfvs);
    EXPECT_TRUE(s.takeRequests().rebuild);
    s.handle({0, EventType::Set, "alpha", "0.2"});
    EXPECT_FLOAT_EQ(s.options().params.common.alpha, 0.2f);
    EXPECT_TRUE(s.takeRequests().rebuild);
    s.handle({0, EventType::Set, "field", "wallShearStress"});
    Requests r = s.takeRequests();
    // The input's options wait in the request until the data is read with them.
    ASSERT_EQ(r.reload.size(), 1u);
    EXPECT_EQ(r.reload[0], std::make_pair(std::string("field"), std::string("wallShearStress")));
    EXPECT_EQ(s.options().field, "");
    // OpenFOAM's patches and case kind are read with the input: set after the first load
    // they read it again (they were once silently ignored).
    s.handle({0, EventType::Set, "patches", "wall.*"});
    EXPECT_FALSE(s.takeRequests().reload.empty());
    s.handle({0, EventType::Set, "foam-case", "decomposed"});
    EXPECT_FALSE(s.takeRequests().reload.empty());
    s.handle({0, EventType::Set, "fov", "45"});
    r = s.takeRequests();
    EXPECT_FALSE(r.rebuild || !r.reload.empty());  // a camera change needs no new renderers
    s.handle({0, EventType::Set, "fps", "60"});
    r = s.takeRequests();
    EXPECT_FALSE(r.rebuild || !r.reload.empty());  // an output setting needs nothing
    s.handle({0, EventType::Set, "alpha", "7"});
    EXPECT_NE(s.error.find("--alpha"), std::string::npos) << s.error;
    EXPECT_FLOAT_EQ(s.options().params.common.alpha, 0.2f);  // unchanged
    s.handle({0, EventType::Key, "j"});
    EXPECT_NE(s.error.find("unknown key 'j'"), std::string::npos);
    s.handle({0, EventType::Set, "compare", "isa,hybrid"});
    EXPECT_EQ(s.shownMethods().size(), 2u);
    EXPECT_EQ(s.viewSize().width, 200);  // the window split in two
    s.handle({0, EventType::Key, "space"});
    EXPECT_TRUE(s.paused);
    EXPECT_FALSE(s.advancing());
    s.handle({0, EventType::Key, "n"});
    EXPECT_TRUE(s.advancing());
    s.frameDone();
    EXPECT_FALSE(s.advancing());
    EXPECT_FALSE(s.stepOnce);
}

// The state's options are its playback's (the one copy the GL side renders with): panel
// and log edits, live ones (dye) included, and the quality setting land there.
TEST(ViewState, OptionsAndQualityLiveInThePlayback) {
    ViewerState s = loaded();
    EXPECT_EQ(&s.options(), &s.playback().options());
    s.handle({0, EventType::Set, "alpha", "0.3"});
    EXPECT_FLOAT_EQ(s.playback().options().params.common.alpha, 0.3f);
    s.handle({0, EventType::Set, "dye", "0,0,1:0.1:red"});
    EXPECT_EQ(s.playback().options().dye.size(), 1u);
    s.handle({0, EventType::Set, "quality", "5"});
    EXPECT_EQ(s.playback().quality().every(), 5);
    s.handle({0, EventType::Set, "quality", "off"});
    EXPECT_EQ(s.playback().quality().every(), 0);
    EXPECT_TRUE(s.error.empty()) << s.error;
}

// Time playback: data time per frame, held at the end (or looped), and the saved batch
// options map frame `clock` to the time on screen.
TEST(ViewState, TimePlaysToTheEndAndBatchOptionsReproduceIt) {
    ViewerState s = loaded({}, {0, 1, 2, 3, 4}, 0.25);
    EXPECT_DOUBLE_EQ(s.time, 0.0);
    for (int k = 0; k < 10; ++k) s.frameDone();
    EXPECT_DOUBLE_EQ(s.time, 2.5);
    RenderOptions b = s.batchOptions(10);  // the noise clock after 10 frames
    EXPECT_EQ(b.frames, 10);
    EXPECT_DOUBLE_EQ(makeTimeMapping(b, {0, 1, 2, 3, 4}).at(b.frames), 2.5);
    for (int k = 0; k < 20; ++k) s.frameDone();
    EXPECT_DOUBLE_EQ(s.time, 4.0);  // held at the end
    b = s.batchOptions(30);
    EXPECT_DOUBLE_EQ(makeTimeMapping(b, {0, 1, 2, 3, 4}).at(b.frames), 4.0);
    s.handle({0, EventType::Key, "left"});
    EXPECT_DOUBLE_EQ(s.time, 3.0);
    EXPECT_FALSE(s.timePlaying);
    b = s.batchOptions(30);
    EXPECT_DOUBLE_EQ(makeTimeMapping(b, {0, 1, 2, 3, 4}).at(b.frames), 3.0);
    s.handle({0, EventType::Set, "time-playing", "true"});
    s.handle({0, EventType::Set, "loop", "true"});
    for (int k = 0; k < 5; ++k) s.frameDone();
    EXPECT_DOUBLE_EQ(s.time, 0.0);  // wrapped past 4
}
