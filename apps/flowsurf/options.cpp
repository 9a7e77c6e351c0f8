#include "options.h"

#include "core/errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace flowsurf::app {

float parseFloat(const std::string& s, const std::string& what) {
    try {
        size_t used = 0;
        float v = std::stof(s, &used);
        if (used != s.size() || !std::isfinite(v)) throw std::invalid_argument(s);
        return v;
    } catch (const std::exception&) {
        throw ConfigError(what + ": '" + s + "' is not a finite number");
    }
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

}  // namespace

core::Viewport parseSize(const std::string& text, const std::string& what) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
        throw ConfigError(what + ": '" + text + "' is not WIDTHxHEIGHT (e.g. 800x600)");
    if (w < 16 || h < 16 || w > 8192 || h > 8192)
        throw ConfigError(what + ": " + text + " is out of range (each side 16..8192 pixels)");
    return {w, h};
}

glm::vec3 parseVec3(const std::string& text, const std::string& what) {
    std::vector<std::string> parts;
    std::stringstream ss(text);
    for (std::string p; std::getline(ss, p, ',');) parts.push_back(p);
    if (parts.size() != 3) throw ConfigError(what + ": '" + text + "' is not x,y,z");
    return {parseFloat(parts[0], what), parseFloat(parts[1], what), parseFloat(parts[2], what)};
}

glm::vec3 parseColor(const std::string& text, const std::string& what) {
    if (!text.empty() && text[0] == '#') {
        unsigned v = 0;
        char extra = 0;
        if (text.size() != 7 || std::sscanf(text.c_str() + 1, "%6x%c", &v, &extra) != 1)
            throw ConfigError(what + ": '" + text + "' is not #RRGGBB");
        return glm::vec3(float((v >> 16) & 255), float((v >> 8) & 255), float(v & 255)) / 255.0f;
    }
    std::string t = lower(text);
    if (t == "black") return glm::vec3(0.0f);
    if (t == "white") return glm::vec3(1.0f);
    if (t == "gray" || t == "grey") return glm::vec3(0.5f);
    glm::vec3 c = parseVec3(text, what);
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(c, glm::vec3(1.0f))))
        throw ConfigError(what + ": components of '" + text + "' must be in 0..1");
    return c;
}

OutputKind outputKind(const std::string& path) {
    std::string l = lower(path);
    auto ends = [&](const std::string& e) { return l.size() >= e.size() && l.compare(l.size() - e.size(), e.size(), e) == 0; };
    if (ends(".mp4")) return OutputKind::Mp4;
    if (ends(".png")) return l.find('%') != std::string::npos ? OutputKind::PngSequence : OutputKind::Png;
    throw ConfigError("--output: '" + path + "' must end in .png, .mp4, or be a %04d.png pattern");
}

void addRenderOptions(CLI::App& cmd, RenderOptions& o) {
    auto& p = o.params;
    cmd.add_option("input", o.input, "Surface file (.vtp .vtu .vtk .ply .obj .stl .foam .e .case .pvd) or builtin:NAME");
    cmd.add_flag("--list-builtins", o.listBuiltins, "List the built-in scenes and exit");

    const std::string gOut = "Output";
    cmd.add_option("-o,--output", o.output, "FILE.png (final composite), FILE.mp4 (all frames) or frame_%04d.png")
        ->group(gOut)->capture_default_str();
    cmd.add_option_function<std::string>("--size", [&o](const std::string& s) { o.size = parseSize(s); },
                                         "Image size WxH in pixels (default 800x600)")->group(gOut);
    cmd.add_option("--frames", o.frames, "Advection frames before the output frame")
        ->group(gOut)->capture_default_str()->check(CLI::Range(0, 100000));
    cmd.add_option("--flow-texture", o.flowTexture, "Also write the advected texture F_a alone (16-bit gray PNG)")
        ->group(gOut);
    cmd.add_option("--fps", o.fps, "MP4 frame rate")->group(gOut)->capture_default_str()->check(CLI::Range(1, 240));
    cmd.add_option("--crf", o.crf, "MP4 H.264 quality, 0 (lossless) .. 51")
        ->group(gOut)->capture_default_str()->check(CLI::Range(0, 51));
    cmd.add_flag("-q,--quiet", o.quiet, "No progress bar or messages")->group(gOut);
    cmd.add_flag("-v,--verbose", o.verbose, "Log the OpenGL renderer and timings")->group(gOut);

    const std::string gData = "Data";
    cmd.add_option("--field", o.field, "Vector array to show (default: the first 3-component point array)")
        ->group(gData);
    cmd.add_option_function<size_t>("--time-step", [&o](size_t s) { o.timeStep = s; o.timeStepGiven = true; },
                                    "Render only this time step (index), as steady data")->group(gData);
    cmd.add_option_function<std::string>("--time", [&o](const std::string& s) {
        auto colon = s.find(':');
        if (colon == std::string::npos) throw ConfigError("--time: '" + s + "' is not START:END");
        o.timeRange = std::make_pair(double(parseFloat(s.substr(0, colon), "--time")),
                                     double(parseFloat(s.substr(colon + 1), "--time")));
    }, "Data time range START:END of the animation (default: the whole series)")->group(gData);
    cmd.add_option("--time-per-frame", o.timePerFrame, "Data time per animation frame")
        ->group(gData)->check(CLI::PositiveNumber);
    cmd.add_option("--frames-per-step", o.framesPerStep, "Animation frames per data time step")
        ->group(gData)->check(CLI::Range(1, 100000));
    cmd.add_option_function<double>("--trace-dt", [&o](double dt) { o.traceDt = dt; },
                                    "Hybrid on a time series: data time per particle step, so the LIC follows "
                                    "pathlines (default: the data time per frame; 0: streamlines of each "
                                    "frame's field)")
        ->group(gData)->check(CLI::NonNegativeNumber);

    const std::string gMethod = "Method";
    cmd.add_option("-m,--method", o.method, "Visualization method")
        ->group(gMethod)->capture_default_str()->check(CLI::IsMember({"isa", "ibfvs", "hybrid"}));
    cmd.add_option("--alpha", p.common.alpha, "Noise blend alpha [L eq. 9], 0..1 (papers: 0.1-0.2)")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(0.0f, 1.0f));
    cmd.add_option("--beta", p.common.beta, "Texture strength beta [L eq. 10], 0..1")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(0.0f, 1.0f));
    cmd.add_option_function<float>("--step-px", [&p](float s) { p.common.stepPx = p.hybrid.stepPx = s; },
                                   "Pixels per step (dt): ISA/IBFVS largest displacement per frame (default 4), "
                                   "hybrid arc length per integration step (default 2)")
        ->group(gMethod)->check(CLI::Range(0.0f, 64.0f));
    cmd.add_option("--speed-percentile", p.common.speedPercentile,
                   "Clamp advection speed at this percentile of the surface's speeds (100: no clamp)")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(1.0f, 100.0f));
    cmd.add_option_function<std::string>("--normalize", [&p](const std::string& s) { p.common.normalize = s == "on"; },
                                         "on: unit-length vectors, uniform streaks (default); off: streak length shows speed")
        ->group(gMethod)->check(CLI::IsMember({"on", "off"}));
    cmd.add_option("--noise-scale", p.common.noise.scale, "Noise cell size s in pixels (papers: 1-10)")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(1.0f, 64.0f));
    cmd.add_option("--noise-period", p.common.noise.period, "Frames per cycle of each noise cell's profile")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(2.0f, 10000.0f));
    cmd.add_option_function<std::string>("--noise-profile", [&p](const std::string& s) {
        p.common.noise.profile = s == "sawtooth" ? core::NoiseProfile::Sawtooth : core::NoiseProfile::Square;
    }, "Periodic profile w of the noise: square or sawtooth (default square)")
        ->group(gMethod)->check(CLI::IsMember({"square", "sawtooth"}));
    cmd.add_option("--seed", p.common.noise.seed, "Noise seed")->group(gMethod)->capture_default_str();
    cmd.add_option("--grid-res", p.isa.gridRes, "ISA advection mesh resolution R (R x R cells)")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(64, 1024));
    cmd.add_option_function<std::string>("--isa-warp", [&p](const std::string& s) {
        p.isa.warp = s == "mesh" ? methods::IsaWarp::Mesh : methods::IsaWarp::Pixel;
    }, "ISA texture advection: pixel (mesh interpolated per pixel, default) or mesh (draw the R x R grid)")
        ->group(gMethod)->check(CLI::IsMember({"pixel", "mesh"}));
    cmd.add_option_function<std::string>("--resample", [&p](const std::string& s) {
        p.common.resample = s == "bilinear" ? methods::Resample::Bilinear : methods::Resample::Bicubic;
    }, "ISA/IBFVS: resampling of the advected texture each frame: bicubic (Catmull-Rom, default) or bilinear ([L])")
        ->group(gMethod)->check(CLI::IsMember({"bilinear", "bicubic"}));
    cmd.add_option_function<std::string>("--noise-injection", [&p](const std::string& s) {
        p.common.noiseInjection = s == "point" ? methods::NoiseInjectionMode::Point : methods::NoiseInjectionMode::Swept;
    }, "ISA/IBFVS: noise G sampled at the pixel (point, [L]) or averaged along its motion over the frame (swept, default)")
        ->group(gMethod)->check(CLI::IsMember({"point", "swept"}));
    cmd.add_flag("--cull-back-faces", p.common.cullBackFaces,
                 "Skip back-facing triangles (closed, outward-oriented surfaces only; default off)")->group(gMethod);
    cmd.add_flag("--edge-mask", p.ibfvs.edgeMask, "IBFVS silhouette edge mask over the image [L §IV-E.2]")
        ->group(gMethod);
    cmd.add_option_function<std::string>("--on-camera-move", [&p](const std::string& s) {
        p.common.onCameraMove = s == "none" ? methods::CameraMoveRemedy::None
                              : s == "freeze" ? methods::CameraMoveRemedy::Freeze
                                              : methods::CameraMoveRemedy::Translate;
    }, "When the camera moves: translate (reproject the texture with the surface, default), freeze, none")
        ->group(gMethod)->check(CLI::IsMember({"translate", "freeze", "none"}));
    cmd.add_option("--filter-length", p.hybrid.filterLength, "Hybrid LIC filter length L in samples ([W] 25-70)")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(1, 1001));
    cmd.add_option_function<std::string>("--kernel", [&p](const std::string& s) {
        p.hybrid.kernel = s == "box" ? methods::LicKernel::Box
                        : s == "exponential" ? methods::LicKernel::Exponential
                        : s == "hann" ? methods::LicKernel::Hann : methods::LicKernel::Gaussian;
    }, "Hybrid LIC kernel: box, exponential, gaussian (default), hann")
        ->group(gMethod)->check(CLI::IsMember({"box", "exponential", "gaussian", "hann"}));
    cmd.add_option_function<std::string>("--integrator", [&p](const std::string& s) {
        p.hybrid.integrator = s == "rk2" ? methods::Integrator::Rk2
                            : s == "rk4" ? methods::Integrator::Rk4 : methods::Integrator::Euler;
    }, "Hybrid particle integrator: euler (default, as in [W]), rk2, rk4")
        ->group(gMethod)->check(CLI::IsMember({"euler", "rk2", "rk4"}));
    cmd.add_option("--noise-size", p.hybrid.noiseSize, "Hybrid solid noise texels per side (64 or 128)")
        ->group(gMethod)->capture_default_str()->check(CLI::IsMember({64, 128}));
    cmd.add_option("--edge-epsilon", p.isa.edgeEpsilon, "ISA edge detection eps [L eq. 14], depth range per pixel")
        ->group(gMethod)->capture_default_str()->check(CLI::Range(0.0f, 10.0f));
    cmd.add_option_function<std::string>("--edge-blending", [&p](const std::string& s) { p.isa.edgeBlending = s == "on"; },
                                         "ISA edge blending on|off (default on)")
        ->group(gMethod)->check(CLI::IsMember({"on", "off"}));

    const std::string gLook = "Overlay";
    cmd.add_option_function<std::string>("--overlay", [&p](const std::string& s) {
        using methods::OverlayScheme;
        p.common.overlay = s == "gray" ? OverlayScheme::Gray
                         : s == "gray-lit" ? OverlayScheme::GrayLit
                         : s == "hue-lit" ? OverlayScheme::HueLit
                         : s == "coolwarm" ? OverlayScheme::CoolWarm : OverlayScheme::Blend;
    }, "blend (eq. 10: texture + colour map x lighting, default); or [W Fig. 6]: gray, gray-lit, hue-lit, coolwarm")
        ->group(gLook)->check(CLI::IsMember({"blend", "gray", "gray-lit", "hue-lit", "coolwarm"}));
    cmd.add_option_function<std::string>("--colormap", [&p](const std::string& s) {
        p.common.colormap = s == "none" ? methods::Colormap::None
                          : s == "coolwarm" ? methods::Colormap::CoolWarm
                          : s == "gray" ? methods::Colormap::Gray : methods::Colormap::Viridis;
    }, "Colour map of speed: viridis, coolwarm, gray, none (default viridis)")
        ->group(gLook)->check(CLI::IsMember({"viridis", "coolwarm", "gray", "none"}));
    cmd.add_option_function<std::string>("--lighting", [&p](const std::string& s) { p.common.lighting = s == "on"; },
                                         "Diffuse lighting on|off (default on)")
        ->group(gLook)->check(CLI::IsMember({"on", "off"}));
    cmd.add_flag("--velocity-mask", p.common.velocityMask, "Texture contrast follows speed [L ref 14]")->group(gLook);
    cmd.add_option("--contrast", p.common.contrast, "Display gain of the flow texture about its mean")
        ->group(gLook)->capture_default_str()->check(CLI::Range(0.0f, 20.0f));
    cmd.add_option_function<std::string>("--background", [&p](const std::string& s) { p.common.background = parseColor(s); },
                                         "Background colour: #RRGGBB, r,g,b in 0..1, black, white, gray")->group(gLook);

    const std::string gCam = "Camera";
    cmd.add_option_function<std::string>("--eye", [&o](const std::string& s) { o.eye = parseVec3(s, "--eye"); },
                                         "Eye position x,y,z (default: fit the bounds)")->group(gCam);
    cmd.add_option_function<std::string>("--target", [&o](const std::string& s) { o.target = parseVec3(s, "--target"); },
                                         "Look-at point x,y,z (default: centre of the bounds)")->group(gCam);
    cmd.add_option_function<std::string>("--up", [&o](const std::string& s) { o.up = parseVec3(s, "--up"); },
                                         "Up vector x,y,z (default 0,1,0)")->group(gCam);
    cmd.add_option("--fov", o.fov, "Vertical field of view in degrees")
        ->group(gCam)->capture_default_str()->check(CLI::Range(1.0f, 170.0f));
    cmd.add_option("--ortho", o.ortho, "Orthographic view with this view height (object units)")
        ->group(gCam)->check(CLI::PositiveNumber);
    cmd.add_option("--orbit", o.orbit, "Camera turns this many degrees per frame about the up axis (dynamic case)")
        ->group(gCam)->capture_default_str()->check(CLI::Range(-180.0f, 180.0f));
    cmd.add_option("--camera-path", o.cameraPath, "Keyframed camera path (JSON); see README")->group(gCam);
}

void validateRenderOptions(const RenderOptions& o) {
    if (o.input.empty()) throw ConfigError("render: an input file or builtin:NAME is required");
    outputKind(o.output);
    if (!o.flowTexture.empty() && outputKind(o.flowTexture) != OutputKind::Png)
        throw ConfigError("--flow-texture: '" + o.flowTexture + "' must be a .png file");
    if (o.timePerFrame > 0.0 && o.framesPerStep > 0)
        throw ConfigError("--time-per-frame and --frames-per-step cannot be combined");
    if (o.timeStepGiven && (o.timeRange || o.timePerFrame > 0.0 || o.framesPerStep > 0))
        throw ConfigError("--time-step renders one step: it cannot be combined with --time, --time-per-frame or --frames-per-step");
    if (!o.cameraPath.empty() && o.orbit != 0.0f) throw ConfigError("--camera-path and --orbit cannot be combined");
    if (o.up && glm::length(*o.up) == 0.0f) throw ConfigError("--up: the up vector must not be zero");
    if (o.eye && o.target && glm::length(*o.eye - *o.target) == 0.0f)
        throw ConfigError("--eye and --target must differ");
}

}  // namespace flowsurf::app
