// Option parsing of `flowsurf render`: the names scripts depend on, and refusals.
#include "core/errors.h"
#include "session/camera_path_file.h"
#include "session/options/config_file.h"
#include "io/text_writer.h"
#include "cli_options.h"
#include "cli_parse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

using namespace flowsurf;
using namespace flowsurf::app;

namespace {
RenderOptions parse(std::vector<std::string> args) { return testing_cli::parseRenderArgs(std::move(args)); }
}  // namespace

TEST(CliOptions, ParsesTheDocumentedNames) {
    RenderOptions o = parse({"builtin:sphere", "--method", "isa", "--size", "640x480", "--frames", "12", "--seed",
                             "9", "--eye", "1,2,3", "--target", "0,0,0", "--up", "0,0,1", "--fov", "40", "--orbit",
                             "2", "--output", "a.mp4", "--flow-texture", "f.png", "--background", "#ff8000",
                             "--grid-res", "128", "--step-px", "3", "--edge-epsilon", "0.02", "--alpha", "0.2",
                             "--noise-scale", "4", "--beta", "0.3", "--edge-blending", "off", "--quiet"});
    EXPECT_EQ(o.input, "builtin:sphere");
    EXPECT_EQ(o.size.width, 640);
    EXPECT_EQ(o.size.height, 480);
    EXPECT_EQ(o.frames, 12);
    EXPECT_EQ(o.params.common.noise.seed, 9u);
    EXPECT_EQ(*o.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(*o.up, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(o.fov, 40.0f);
    EXPECT_FLOAT_EQ(o.orbit, 2.0f);
    EXPECT_EQ(o.output, "a.mp4");
    EXPECT_EQ(o.flowTexture, "f.png");
    EXPECT_NEAR(o.params.common.background.g, 128.0f / 255.0f, 1e-6f);
    EXPECT_EQ(o.params.isa.gridRes, 128);
    EXPECT_FLOAT_EQ(o.params.common.stepPx, 3.0f);
    EXPECT_FLOAT_EQ(o.params.isa.edgeEpsilon, 0.02f);
    EXPECT_FLOAT_EQ(o.params.common.alpha, 0.2f);
    EXPECT_FLOAT_EQ(o.params.common.noise.scale, 4.0f);
    EXPECT_FLOAT_EQ(o.params.common.beta, 0.3f);
    EXPECT_FALSE(o.params.isa.edgeBlending);
    EXPECT_TRUE(o.quiet);
    EXPECT_NO_THROW(validateRenderOptions(o));
}

// Sharper defaults for ISA and IBFVS; the paper's behaviour [L] by options.
TEST(CliOptions, PaperResamplingAndNoiseReachable) {
    RenderOptions d = parse({"builtin:sphere"});
    EXPECT_EQ(d.params.common.resample, methods::Resample::Bicubic);
    EXPECT_EQ(d.params.common.noiseInjection, methods::NoiseInjectionMode::Swept);
    EXPECT_FLOAT_EQ(d.params.common.stepPx, 4.0f);
    EXPECT_FLOAT_EQ(d.params.hybrid.stepPx, 2.0f);
    RenderOptions o = parse({"builtin:sphere", "--resample", "bilinear", "--noise-injection", "point", "--step-px", "2",
                             "--lic-step-px", "1.5"});
    EXPECT_EQ(o.params.common.resample, methods::Resample::Bilinear);
    EXPECT_EQ(o.params.common.noiseInjection, methods::NoiseInjectionMode::Point);
    EXPECT_FLOAT_EQ(o.params.common.stepPx, 2.0f);
    EXPECT_FLOAT_EQ(o.params.hybrid.stepPx, 1.5f);  // each method's own step
    EXPECT_THROW(parse({"x", "--resample", "lanczos"}), ConfigError);
    EXPECT_THROW(parse({"x", "--noise-injection", "line"}), ConfigError);
}

TEST(CliOptions, RefusesOutOfRangeAndUnknownValues) {
    EXPECT_THROW(parse({"x", "--grid-res", "32"}), ConfigError);
    EXPECT_THROW(parse({"x", "--grid-res", "2048"}), ConfigError);
    EXPECT_THROW(parse({"x", "--method", "lic"}), ConfigError);
    EXPECT_THROW(parse({"x", "--alpha", "1.5"}), ConfigError);
    EXPECT_THROW(parse({"x", "--frames", "-1"}), ConfigError);
    EXPECT_THROW(parse({"x", "--size", "0x100"}), ConfigError);
    EXPECT_THROW(parse({"x", "--size", "100000x100000"}), ConfigError);
    EXPECT_THROW(parse({"x", "--size", "big"}), ConfigError);
    EXPECT_THROW(parse({"x", "--eye", "1,2"}), ConfigError);
    EXPECT_THROW(parse({"x", "--eye", "1,nan,2"}), ConfigError);
    EXPECT_THROW(parse({"x", "--background", "#12345"}), ConfigError);
}

TEST(CliOptions, OutputKindsAndValidation) {
    EXPECT_EQ(outputKind("a.png"), OutputKind::Png);
    EXPECT_EQ(outputKind("A.MP4"), OutputKind::Mp4);
    EXPECT_EQ(outputKind("f_%04d.png"), OutputKind::PngSequence);
    EXPECT_THROW(outputKind("a.gif"), ConfigError);
    RenderOptions o = parse({"x", "--output", "a.png", "--flow-texture", "f.mp4"});
    EXPECT_THROW(validateRenderOptions(o), ConfigError);
    RenderOptions noInput;
    EXPECT_THROW(validateRenderOptions(noInput), ConfigError);
}

TEST(CliOptions, SizeAndColourSyntaxes) {
    EXPECT_EQ(parseSize("1920x1080").width, 1920);
    EXPECT_EQ(parseSize("16X16").height, 16);
    EXPECT_THROW(parseSize("1920x1080x3"), ConfigError);
    EXPECT_EQ(parseColor("white"), glm::vec3(1.0f));
    EXPECT_EQ(parseColor("0,0.5,1"), glm::vec3(0, 0.5f, 1));
    EXPECT_THROW(parseColor("0,0.5,2"), ConfigError);
    EXPECT_EQ(parseColor("Magenta"), glm::vec3(1, 0, 1));
    // An unknown name says what a colour may be, names included.
    try {
        parseColor("purplish", "--dye");
        ADD_FAILURE() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("--dye: 'purplish' is not a colour"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cyan"), std::string::npos) << e.what();
    }
    // --time takes two numbers: a third is refused as not START:END (Python's time=(a, b, c)).
    RenderOptions o;
    setOption(o, "time", "0.5:2");
    EXPECT_EQ(o.timeRange, std::make_pair(0.5, 2.0));
    try {
        setOption(o, "time", "0:1:2");
        ADD_FAILURE() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("--time: '0:1:2' is not START:END"), std::string::npos) << e.what();
    }
}

// What a method list (--methods, the viewer's compare) and a view preset read as.
TEST(CliOptions, MethodListsAndViewPresetsParseOnce) {
    EXPECT_EQ(parseMethodList("isa,,hybrid", "--methods"),
              (std::vector<methods::Method>{methods::Method::Isa, methods::Method::Hybrid}));
    EXPECT_TRUE(parseMethodList("", "--methods").empty());
    try {
        parseMethodList("isa,lic", "--methods");
        ADD_FAILURE() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("--methods: 'lic' is not one of isa, ibfvs, hybrid"), std::string::npos)
            << e.what();
    }
    RenderOptions o;
    setOption(o, "view", "-z");
    EXPECT_EQ(o.view, ViewPreset::MinusZ);
    EXPECT_EQ(findOption("view")->get(o), "-z");
    setOption(o, "view", "");
    EXPECT_EQ(o.view, ViewPreset::Default);
    try {
        setOption(o, "view", "top");
        ADD_FAILURE() << "no error";
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("--view: 'top' is not one of +x, -x, +y, -y, +z, -z, iso"),
                  std::string::npos) << e.what();
    }
}

// Every option of the table: its default text reads back to the default, and the
// help shows it (defaults are printed from the structs, never retyped).
TEST(CliOptions, TableDefaultsRoundTrip) {
    for (const OptionSpec& spec : renderOptionTable()) {
        RenderOptions o;
        const std::string d = defaultText(spec);
        if (d.empty() || spec.name == "input") continue;
        EXPECT_NO_THROW(spec.set(o, d)) << spec.name << " = " << d;
        EXPECT_EQ(spec.get(o), d) << spec.name;
    }
    RenderOptions o;
    setOption(o, "filter-length", "45");
    setOption(o, "kernel", "hann");
    setOption(o, "edge-mask", "true");
    EXPECT_EQ(o.params.hybrid.filterLength, 45);
    EXPECT_EQ(o.params.hybrid.kernel, methods::LicKernel::Hann);
    EXPECT_TRUE(o.params.ibfvs.edgeMask);
    EXPECT_THROW(setOption(o, "no-such-option", "1"), ConfigError);
    EXPECT_THROW(setOption(o, "filter-length", "4.5"), ConfigError);
    EXPECT_THROW(setOption(o, "kernel", "triangle"), ConfigError);
}

// A saved state reads back to the same options, exactly (floats included), and the
// file's values are overridden by options applied after it.
TEST(CliOptions, ConfigFileRoundTrip) {
    RenderOptions a;
    a.input = "builtin:tori";
    a.method = methods::Method::Hybrid;
    a.size = {321, 123};
    a.eye = glm::vec3(1.0f / 3.0f, -2.7182817f, 12345.678f);
    a.target = glm::vec3(0.1f, 0.2f, 0.3f);
    a.up = glm::vec3(0, 0, 1);
    a.fov = 33.3f;
    a.timeRange = std::make_pair(0.1, 0.7);
    a.params.common.alpha = 0.123f;
    a.params.common.background = {0.2f, 0.4f, 0.6f};
    a.params.hybrid.integrator = methods::Integrator::Rk4;
    a.params.ibfvs.edgeMask = true;
    a.params.common.normalize = false;
    const std::string path = ::testing::TempDir() + "flowsurf_config_roundtrip.json";
    io::writeTextFile(path, configJson(a));
    RenderOptions b;
    applyConfigFile(path, b);
    for (const OptionSpec& spec : renderOptionTable())
        if (spec.takes(FrontEnd::Config)) {
            EXPECT_EQ(spec.get(b), spec.get(a)) << spec.name;
        }
    EXPECT_EQ(*b.eye, *a.eye);
    EXPECT_EQ(b.params.common.background, a.params.common.background);
    std::remove(path.c_str());
}

// A JSON array is the option's numbers joined by its row's separator: [64, 48] is 64x48,
// [0.5, 2] as time and [0, 2.5] as a colour range are START:END and MIN:MAX.
TEST(CliOptions, ConfigArraysAreJoinedAsTheRowSays) {
    const std::string path = ::testing::TempDir() + "flowsurf_config_arrays.json";
    io::writeTextFile(path, "{\"size\": [64, 48], \"time\": [0.5, 2], \"color-range\": [0, 2.5], \"eye\": [0, 0, 5]}");
    RenderOptions o;
    applyConfigFile(path, o);
    EXPECT_EQ(findOption("size")->get(o), "64x48");
    EXPECT_EQ(findOption("time")->get(o), "0.5:2");
    EXPECT_EQ(findOption("color-range")->get(o), "0:2.5");
    EXPECT_EQ(findOption("eye")->get(o), "0,0,5");
    std::remove(path.c_str());
}

TEST(CliOptions, ConfigFileErrorsNameFileAndKey) {
    const std::string path = ::testing::TempDir() + "flowsurf_config_bad.json";
    auto write = [&](const char* text) { std::FILE* f = std::fopen(path.c_str(), "w"); std::fputs(text, f); std::fclose(f); };
    RenderOptions o;
    write("{\"alpha\": 7}");
    try {
        applyConfigFile(path, o);
        FAIL() << "out-of-range alpha accepted";
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("flowsurf_config_bad.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("alpha"), std::string::npos) << e.what();
    }
    write("{\"colour\": \"red\"}");
    EXPECT_THROW(applyConfigFile(path, o), ConfigError);
    write("{\"alpha\": ");
    EXPECT_THROW(applyConfigFile(path, o), FormatError);
    write("[1, 2]");
    EXPECT_THROW(applyConfigFile(path, o), FormatError);
    write("{\"time-step\": \"1e46\"}");  // beyond size_t: was undefined behaviour (found by fuzz_options)
    EXPECT_THROW(applyConfigFile(path, o), ConfigError);
    write("{\"alpha\": 1e99999}");  // nlohmann throws out_of_range, not parse_error (found by fuzz_config)
    EXPECT_THROW(applyConfigFile(path, o), FormatError);
    write("{\"keyframes\": [{\"frame\": 0, \"eye\": [0, 7e923384, 0]}]}");  // found by fuzz_camera_path
    EXPECT_THROW(session::readCameraPath(path, core::Camera{}), FormatError);
    EXPECT_THROW(applyConfigFile(path + ".missing", o), IoError);
    std::remove(path.c_str());
    const char* argv[] = {"flowsurf", "render", "--config", "a.json", "-o", "x.png"};
    EXPECT_EQ(findConfigArgument(6, argv).value(), "a.json");
}

// A folder where a JSON file is expected is an IoError, not an uncaught stream failure
// (found by fuzz_options: --colormap-file /).
TEST(CliOptions, JsonFileThatIsAFolderIsAnIoError) {
    RenderOptions o;
    EXPECT_THROW(applyConfigFile(::testing::TempDir(), o), IoError);
    EXPECT_THROW(setOption(o, "colormap-file", ::testing::TempDir()), IoError);
}

// What a change of each option means is declared once, in the table; the front ends (the
// viewer, flowsurf::Renderer, Python, ParaView) read it from there.
TEST(CliOptions, EachOptionDeclaresItsEffect) {
    EXPECT_EQ(effectOf("patches"), OptionEffect::Reload);  // once silently ignored after the first load
    EXPECT_EQ(effectOf("foam-case"), OptionEffect::Reload);
    EXPECT_EQ(effectOf("input"), OptionEffect::Reload);
    EXPECT_EQ(effectOf("alpha"), OptionEffect::Rebuild);
    EXPECT_EQ(effectOf("method"), OptionEffect::Rebuild);
    EXPECT_EQ(effectOf("warmup"), OptionEffect::Rebuild);
    EXPECT_EQ(effectOf("eye"), OptionEffect::Camera);
    EXPECT_EQ(effectOf("orbit"), OptionEffect::Camera);
    EXPECT_EQ(effectOf("fps"), OptionEffect::Output);
    EXPECT_EQ(effectOf("quiet"), OptionEffect::None);
    EXPECT_THROW(effectOf("no-such-option"), ConfigError);
    // Several changes need the largest effect among them.
    RenderOptions a, b;
    EXPECT_EQ(changeEffect(a, b), OptionEffect::None);
    setOption(b, "fov", "40");
    EXPECT_EQ(changeEffect(a, b), OptionEffect::Camera);
    setOption(b, "kernel", "box");
    EXPECT_EQ(changeEffect(a, b), OptionEffect::Rebuild);
    setOption(b, "patches", "wall.*");
    EXPECT_EQ(changeEffect(a, b), OptionEffect::Reload);
}

// Lists of names in messages and --help come from the tables.
TEST(CliOptions, NameListsComeFromTheTables) {
    try {
        parse({"x", "--method", "lic"});
        FAIL();
    } catch (const ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("'lic' is not one of " + methods::nameList(methods::kMethodNames)),
                  std::string::npos) << e.what();
    }
    EXPECT_EQ(methods::nameList(methods::kMethodNames), "isa, ibfvs, hybrid");
    methods::Method m{};
    EXPECT_TRUE(methods::valueOf(methods::kMethodNames, "hybrid", &m));
    EXPECT_EQ(m, methods::Method::Hybrid);
    EXPECT_EQ(methods::nameOf(methods::kMethodNames, methods::Method::Ibfvs), "ibfvs");
    EXPECT_EQ(parse({"x", "-m", "ibfvs"}).method, methods::Method::Ibfvs);
}

// Each row declares the front ends that take it; the front ends and the manual's option
// reference (tools/docs/option_reference.cpp) read them from there.
TEST(CliOptions, FrontEndsOfEachOption) {
    auto spec = [](const char* name) { return *findOption(name); };
    EXPECT_EQ(paraviewProperty(spec("filter-length")), "FlowSurfFilterLength");
    EXPECT_EQ(paraviewProperty(spec("warmup")), "FlowSurfWarmup");
    EXPECT_EQ(paraviewProperty(spec("colormap")), "");   // ParaView's own colouring
    EXPECT_EQ(paraviewProperty(spec("size")), "");       // the view's size
    EXPECT_TRUE(spec("alpha").takes(FrontEnd::Renderer));
    EXPECT_FALSE(spec("output").takes(FrontEnd::Renderer));  // the caller writes its files
    EXPECT_FALSE(spec("patches").takes(FrontEnd::Renderer)); // read with the surface
    EXPECT_TRUE(spec("patches").takes(FrontEnd::Read));
    EXPECT_FALSE(spec("field").takes(FrontEnd::Read));        // read()'s own argument
    EXPECT_TRUE(spec("alpha").takes(FrontEnd::Panel));
    EXPECT_TRUE(spec("eye").takes(FrontEnd::Panel));
    EXPECT_FALSE(spec("orbit").takes(FrontEnd::Panel));
    EXPECT_TRUE(spec("method").takes(FrontEnd::PanelOwn));   // buttons of their own, not a widget
    EXPECT_FALSE(spec("method").takes(FrontEnd::Panel));
    EXPECT_FALSE(spec("quiet").takes(FrontEnd::Config));     // messages are not a saved state
    EXPECT_EQ(groupName(spec("dye").role.group), "Dye");
}

// What the rows declare agrees with what the front ends do with them: what is read (Reload)
// belongs to the surface and what is written (Output) to the caller, never to a Renderer;
// the options of reading are reloads; the command line takes every option once.
TEST(CliOptions, RolesAgreeWithEffects) {
    int positional = 0;
    for (const OptionSpec& s : renderOptionTable()) {
        const OptionEffect e = s.role.effect;
        EXPECT_EQ(s.takes(FrontEnd::Renderer), e != OptionEffect::Reload && e != OptionEffect::Output) << s.name;
        EXPECT_TRUE(!s.takes(FrontEnd::Read) || e == OptionEffect::Reload) << s.name;
        EXPECT_NE(s.takes(FrontEnd::CommandLine), s.takes(FrontEnd::Positional)) << s.name;
        EXPECT_FALSE(s.takes(FrontEnd::Panel) && s.takes(FrontEnd::PanelOwn)) << s.name;
        EXPECT_EQ(s.role.effect == OptionEffect::Camera, s.role.group == OptionGroup::Camera) << s.name;
        positional += s.takes(FrontEnd::Positional);
    }
    EXPECT_EQ(positional, 1);
}

// Each row says which methods it changes: a row whose help names its methods ("ISA/IBFVS:",
// "Hybrid", "IBFVS silhouette", ...) applies to those alone, every other row to all of them,
// and every row to at least one.
TEST(CliOptions, RowsSayWhichMethodsTheyApplyTo) {
    using methods::Method;
    auto applies = [](const char* name) {
        std::string out;
        for (const auto& [m, text] : methods::kMethodNames)
            if (findOption(name)->appliesTo(m)) out += (out.empty() ? "" : ",") + std::string(text);
        return out;
    };
    EXPECT_EQ(applies("alpha"), "isa,ibfvs");
    EXPECT_EQ(applies("step-px"), "isa,ibfvs");
    EXPECT_EQ(applies("grid-res"), "isa");
    EXPECT_EQ(applies("edge-mask"), "ibfvs");
    EXPECT_EQ(applies("filter-length"), "hybrid");
    EXPECT_EQ(applies("lic-step-px"), "hybrid");
    EXPECT_EQ(applies("noise-scale"), "isa,ibfvs,hybrid");
    EXPECT_EQ(applies("method"), "isa,ibfvs,hybrid");
    EXPECT_EQ(applies("colormap"), "isa,ibfvs,hybrid");
    EXPECT_EQ(applies("trace-dt"), "hybrid");
    for (const OptionSpec& s : renderOptionTable()) {
        const bool some = s.role.methods.bits != kEveryMethod.bits;
        const std::string head = s.help.substr(0, s.help.find(' '));
        const bool named = head == "ISA" || head == "ISA/IBFVS:" || head == "IBFVS" || head == "Hybrid" ||
                           head == "Hybrid:";
        EXPECT_TRUE(!named || some) << s.name << ": its help names its methods, its row does not";
        EXPECT_TRUE(std::any_of(std::begin(methods::kMethodNames), std::end(methods::kMethodNames),
                                [&](const auto& m) { return s.appliesTo(m.first); }))
            << s.name;
    }
}
