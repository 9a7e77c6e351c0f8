// The public C++ API as a consumer uses it (only <flowsurf/flowsurf.h>): contexts, arrays,
// animation, errors. Links libflowsurf.so; the "caller's context" is made here with EGL.
#include <flowsurf/flowsurf.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

struct Arrays {
    std::vector<float> points, vectors;
    std::vector<uint32_t> triangles;
};

// A 33 x 33 grid on z = 0 with a vortex about its centre.
Arrays vortexPlane() {
    Arrays a;
    const int n = 33;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            float x = -1.0f + 2.0f * i / (n - 1), y = -1.0f + 2.0f * j / (n - 1);
            a.points.insert(a.points.end(), {x, y, 0.0f});
            a.vectors.insert(a.vectors.end(), {-y, x, 0.0f});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            uint32_t v = uint32_t(j * n + i);
            a.triangles.insert(a.triangles.end(), {v, v + 1, v + uint32_t(n), v + 1, v + uint32_t(n) + 1, v + uint32_t(n)});
        }
    return a;
}

flowsurf::Surface surfaceOf(const Arrays& a) {
    return flowsurf::Surface::fromArrays(a.points.data(), a.points.size() / 3, a.triangles.data(),
                                         a.triangles.size() / 3, a.vectors.data(), "swirl");
}

std::vector<uint8_t> image(const flowsurf::Renderer& r) {
    std::vector<uint8_t> rgb(size_t(r.width()) * r.height() * 3);
    r.readImage(rgb.data());
    return rgb;
}

// A current OpenGL 4.5 core context of the caller's own (surfaceless EGL).
class CallerContext {
public:
    CallerContext() {
        auto getDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        dpy_ = getDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        eglInitialize(dpy_, nullptr, nullptr);
        eglBindAPI(EGL_OPENGL_API);
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        ctx_ = eglCreateContext(dpy_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
        ok_ = ctx_ != EGL_NO_CONTEXT && eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_);
    }
    ~CallerContext() {
        eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (ctx_ != EGL_NO_CONTEXT) eglDestroyContext(dpy_, ctx_);
    }
    bool ok() const { return ok_; }

private:
    EGLDisplay dpy_ = EGL_NO_DISPLAY;
    EGLContext ctx_ = EGL_NO_CONTEXT;
    bool ok_ = false;
};

}  // namespace

// The library's own context and a caller's current one render the same image.
TEST(Api, OwnAndCallerContextsRenderTheSameImage) {
    const flowsurf::Surface s = surfaceOf(vortexPlane());
    flowsurf::Renderer own;
    own.set("size", "96x80");
    own.set("method", "isa");
    own.render(s, 20);
    const std::vector<uint8_t> a = image(own);
    CallerContext caller;
    ASSERT_TRUE(caller.ok()) << "no surfaceless EGL 4.5 context";
    flowsurf::Renderer borrowed(flowsurf::ContextMode::Current);
    borrowed.set("size", "96x80");
    borrowed.set("method", "isa");
    borrowed.render(s, 20);
    EXPECT_EQ(image(borrowed), a);
    EXPECT_NE(a, std::vector<uint8_t>(a.size(), a[0]));  // not a blank image
}

// begin + advance animate frame by frame: the frame count, the orbit turning the camera,
// and without a warm-up frame N equal to render(N).
TEST(Api, AnimationFrameByFrameEqualsOneRender) {
    const flowsurf::Surface s = surfaceOf(vortexPlane());
    flowsurf::Renderer r;
    r.set("size", "64x64");
    r.set("method", "ibfvs");
    r.set("orbit", "2");
    r.set("warmup", "0");
    r.begin(s);
    for (int k = 0; k <= 10; ++k) r.advance();
    EXPECT_EQ(r.frame(), 11);
    const std::vector<uint8_t> stepped = image(r);
    const flowsurf::CameraView cam = r.camera();
    r.render(s, 10);
    EXPECT_EQ(image(r), stepped);
    EXPECT_EQ(r.camera().eye[0], cam.eye[0]);
    std::vector<float> flow(64 * 64);
    r.readFlowTexture(flow.data());
    for (float v : flow) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
    EXPECT_FALSE(r.stageMs().empty());
}

TEST(Api, BadArraysAndOptionsThrowTypedErrorsNamingTheItem) {
    Arrays a = vortexPlane();
    a.triangles[7] = 100000;
    try {
        surfaceOf(a);
        FAIL() << "index out of range accepted";
    } catch (const flowsurf::FormatError& e) {
        EXPECT_NE(std::string(e.what()).find("triangle 2"), std::string::npos) << e.what();
    }
    a = vortexPlane();
    a.vectors[3 * 12 + 1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(surfaceOf(a), flowsurf::FormatError);
    flowsurf::Surface s = surfaceOf(vortexPlane());
    EXPECT_THROW(s.setField("pressure"), flowsurf::FieldError);
    flowsurf::Renderer r;
    EXPECT_THROW(r.set("filter-length", "0"), flowsurf::ConfigError);
    EXPECT_THROW(r.set("no-such-option", "1"), flowsurf::ConfigError);
    EXPECT_THROW(r.advance(), flowsurf::ConfigError);  // nothing begun
    EXPECT_THROW(flowsurf::Surface::read("/nonexistent/case.vtp"), flowsurf::IoError);
    EXPECT_EQ(r.get("filter-length"), "31");  // the CLI's default
}

// An animation starts converged, as the command line's movie: the warm-up (3 / alpha
// frames by default) runs at frame 0's camera before frame 0, whose noise clock is then
// W. With a fixed camera, frame 0 is the image render(W) writes (frames 0..W at k = 0..W).
TEST(Api, AnimationStartsConvergedAsTheCommandLinesMovie) {
    const flowsurf::Surface s = surfaceOf(vortexPlane());
    flowsurf::Renderer r;
    r.set("size", "64x48");
    r.set("method", "isa");
    r.set("alpha", "0.1");  // W = 3 / alpha = 30
    r.begin(s);
    r.advance();
    EXPECT_EQ(r.frame(), 1);
    const std::vector<uint8_t> first = image(r);
    r.render(s, 30);
    EXPECT_EQ(image(r), first);
    r.render(s, 0);
    EXPECT_NE(image(r), first);  // an unconverged start looks different
    // The hybrid is history free: no warm-up; its animation's frame 0 is render(0).
    r.set("method", "hybrid");
    r.begin(s);
    r.advance();
    const std::vector<uint8_t> hybrid = image(r);
    r.render(s, 0);
    EXPECT_EQ(image(r), hybrid);
}

// The arrays out are the arrays in, exactly; each step of a series whose mesh changes has
// its own; a bad array name or step is an error that names what there is.
TEST(Api, ArraysOutAreTheStoredArraysOfEachStep) {
    const Arrays in = vortexPlane();
    const flowsurf::Surface s = surfaceOf(in);
    EXPECT_EQ(s.points(), in.points);
    EXPECT_EQ(s.triangles(), in.triangles);
    const flowsurf::PointArray swirl = s.pointArray("swirl");
    EXPECT_EQ(swirl.components, 3);
    EXPECT_EQ(swirl.values, in.vectors);
    EXPECT_EQ(s.arrays().arrayNames(), std::vector<std::string>{"swirl"});
    try {
        s.pointArray("pressure");
        FAIL() << "a missing array was found";
    } catch (const flowsurf::FieldError& e) {
        EXPECT_NE(std::string(e.what()).find("no point array 'pressure' (has: swirl)"), std::string::npos) << e.what();
    }
    try {
        s.points(1);
        FAIL() << "step 1 of one";
    } catch (const flowsurf::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("step 1 is out of range (the surface has one step, 0)"), std::string::npos)
            << e.what();
    }

    // The piston's mesh changes over its 25 steps (streamed): each step's own points.
    const flowsurf::Surface piston = flowsurf::Surface::read("builtin:piston");
    ASSERT_EQ(piston.stepCount(), 25u);
    const flowsurf::SurfaceArrays first = piston.arrays(0), later = piston.arrays(12);  // bottom dead centre
    EXPECT_EQ(first.pointCount(), piston.pointCount());
    EXPECT_GT(later.pointCount(), first.pointCount()) << "the cylinder is longer: more points";
    EXPECT_DOUBLE_EQ(later.time, piston.times()[12]);
    for (const flowsurf::SurfaceArrays* a : {&first, &later}) {
        for (uint32_t i : a->triangles) EXPECT_LT(i, a->pointCount());
        for (const auto& array : a->arrays)
            EXPECT_EQ(array.values.size(), a->pointCount() * size_t(array.components)) << array.name;
    }
    EXPECT_THROW(piston.arrays(25), flowsurf::ConfigError);
}

// What an option change means is the option table's: options read with the input belong
// to the Surface (they were once accepted here and silently ignored), output files to the
// command line; a camera change keeps the frame count; a parameter change starts over.
TEST(Api, OptionsAreAppliedAsTheTableSays) {
    flowsurf::Renderer r;
    for (const char* input : {"patches", "foam-case", "foam-zero-time", "field", "input"}) {
        try {
            r.set(input, "auto");
            FAIL() << input << " accepted by a Renderer";
        } catch (const flowsurf::ConfigError& e) {
            EXPECT_NE(std::string(e.what()).find("Surface"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(r.set("output", "a.png"), flowsurf::ConfigError);
    EXPECT_THROW(flowsurf::Surface::read("builtin:sphere", "", {{"alpha", "0.1"}}), flowsurf::ConfigError);
    EXPECT_THROW(flowsurf::Surface::read("builtin:sphere", "", {{"foam-case", "sideways"}}), flowsurf::ConfigError);
    EXPECT_NO_THROW(flowsurf::Surface::read("builtin:sphere", "", {{"patches", "wall.*"}}));
    const std::vector<std::string> names = flowsurf::Renderer::optionNames();
    EXPECT_EQ(std::count(names.begin(), names.end(), "patches"), 0);
    EXPECT_EQ(std::count(names.begin(), names.end(), "alpha"), 1);

    const flowsurf::Surface s = surfaceOf(vortexPlane());
    r.set("size", "48x48");
    r.set("warmup", "0");
    r.begin(s);
    for (int k = 0; k < 3; ++k) r.advance();
    r.set("orbit", "5");  // the camera: frames go on
    r.advance();
    EXPECT_EQ(r.frame(), 4);
    r.set("alpha", "0.2");  // new renderers: the animation starts over
    r.advance();
    EXPECT_EQ(r.frame(), 1);
}

// Renderer::quality(): measured while rendering (the last frame and, for the
// correlations, the one before) or, with measuring off, the last frame measured on
// demand: the same image gives the same numbers, without correlations.
TEST(Api, QualityOfTheLastFrame) {
    const flowsurf::Surface s = surfaceOf(vortexPlane());
    flowsurf::Renderer r;
    r.set("size", "96x96");
    EXPECT_THROW(r.quality(), flowsurf::ConfigError);
    r.render(s, 30);
    const flowsurf::Quality now = r.quality();
    r.setQualityEvery(1);
    r.render(s, 30);
    const flowsurf::Quality kept = r.quality();
    EXPECT_EQ(now.frames, 1);
    EXPECT_EQ(kept.frames, 1);
    EXPECT_EQ(now.median.orientationErrorDeg, kept.median.orientationErrorDeg);
    EXPECT_EQ(now.median.frequencyPx, kept.median.frequencyPx);
    EXPECT_LT(kept.median.orientationErrorDeg, 10.0);
    EXPECT_TRUE(std::isnan(now.median.frameCorrelation));
    EXPECT_GT(kept.median.frameCorrelation, 0.5);
    const auto named = kept.median.named();
    ASSERT_EQ(named.size(), 8u);
    EXPECT_EQ(named.front().first, "orientation_error_deg");
    EXPECT_EQ(named.front().second, kept.median.orientationErrorDeg);
    EXPECT_THROW(r.setQualityEvery(-1), flowsurf::ConfigError);
}

// Dye [doc/algorithms.md §10] through the library: addDye is the "dye" option's list plus one; the ink
// shows where released (the vortex turns it about the centre) and a bad colour throws.
TEST(Api, AddDyeReleasesInkThatTheFlowCarries) {
    const Arrays a = vortexPlane();
    flowsurf::Surface s = surfaceOf(a);
    flowsurf::Renderer r;
    r.set("size", "96x96");
    r.set("overlay", "gray");
    r.set("lighting", "off");
    r.set("time-per-frame", "0.05");
    r.set("dye-release", "1");  // a blob
    flowsurf::CameraView front;
    front.eye[2] = 4.0f;
    r.setCamera(front);
    r.addDye({0.5f, 0.0f, 0.0f}, 0.1f, "red");
    EXPECT_EQ(r.get("dye"), "0.5,0,0:0.1:#ff0000");
    EXPECT_THROW(r.addDye({0.0f, 0.0f, 0.0f}, 0.1f, "no-such-colour"), flowsurf::ConfigError);
    EXPECT_THROW(r.addDye({0.0f, 0.0f, 0.0f}, -1.0f), flowsurf::ConfigError);
    r.render(s, 20);
    const std::vector<uint8_t> rgb = image(r);
    double red = 0.0, cx = 0.0, cy = 0.0;
    for (int y = 0; y < 96; ++y)
        for (int x = 0; x < 96; ++x) {
            const uint8_t* c = &rgb[(size_t(y) * 96 + x) * 3];
            const double v = std::max(0, int(c[0]) - int(c[1])) / 255.0;
            red += v, cx += v * x, cy += v * y;
        }
    ASSERT_GT(red, 10.0);
    // Counter-clockwise by 20 * 0.05 = 1 radian from (0.5, 0): up and to the left of where it began.
    const double angle = std::atan2(-(cy / red - 47.5), cx / red - 47.5);
    EXPECT_NEAR(angle, 1.0, 0.1);
}

TEST(Api, TopologyOfTheShownFieldAsTheCommandLineFindsIt) {
    // A plane with a vortex about its centre: one centre, index 1, on a disc (chi 1).
    const Arrays a = vortexPlane();
    flowsurf::Surface s = flowsurf::Surface::fromArrays(a.points.data(), a.points.size() / 3, a.triangles.data(),
                                                        a.triangles.size() / 3, a.vectors.data());
    const flowsurf::Topology t = s.topology();
    ASSERT_EQ(t.criticalPoints.size(), 1u);
    EXPECT_EQ(t.criticalPoints[0].index, 1);
    EXPECT_EQ(t.eulerCharacteristic, 1);
    EXPECT_FALSE(t.closed);
    EXPECT_FALSE(t.fieldReversed);
    // The sphere's constant-direction field: a source and a sink, swapped when reversed.
    const flowsurf::Surface tori = flowsurf::Surface::read("builtin:tori");
    auto count = [](const flowsurf::Topology& r, const char* type) {
        return std::count_if(r.criticalPoints.begin(), r.criticalPoints.end(),
                             [&](const flowsurf::CriticalPoint& p) { return p.type == type; });
    };
    const flowsurf::Topology plain = tori.topology(), reversed = tori.topology(0, {{"reverse-field", "on"}});
    EXPECT_TRUE(reversed.fieldReversed);
    EXPECT_GT(count(plain, "source"), 0);
    EXPECT_EQ(count(plain, "source"), count(reversed, "sink"));
    EXPECT_EQ(count(plain, "sink"), count(reversed, "source"));
    EXPECT_THROW(tori.topology(3), flowsurf::ConfigError);
    EXPECT_THROW(tori.topology(0, {{"topology-cancel-speed", "2"}}), flowsurf::ConfigError);
    EXPECT_THROW(tori.topology(0, {{"no-such-option", "1"}}), flowsurf::ConfigError);
}
