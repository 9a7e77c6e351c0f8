// flowsurf — the option table's Method rows: the method and its parameters (noise, advection,
// each method's stages, where the GPU work runs). Each row declares its role: a change
// rebuilds the renderers; every front end takes them, the viewer's panel as widgets made from
// their kinds (the method as buttons of its own).
#include "params/gl_path_rules.h"
#include "session/options/option_rows.h"

namespace flowsurf::session::rows {

namespace {

// "on llvmpipe with at most 1 core when triangles >= 3 x pixels, on llvmpipe when ..., on
// H100 when ..." from the auto rule itself.
std::string computeRasterRuleText() {
    std::string text;
    for (const methods::ComputeRasterRule& rule : methods::kComputeRasterRule)
        text += std::string(text.empty() ? "on " : ", on ") + std::string(rule.renderer) +
                (rule.maxCores ? " with at most " + std::to_string(rule.maxCores) + (rule.maxCores == 1 ? " core" : " cores") : "") +
                " when triangles >= " + formatDouble(rule.trianglesPerPixel) + " x pixels";
    return text;
}

// The method, the noise [L eq. 9] and the advection that ISA and IBFVS share.
std::vector<OptionSpec> noiseAndAdvectionRows() {
    return {
        shortNamed("m", choice("method", {G::Method, E::Rebuild, CommandLine | Config | PanelOwn | Renderer | ParaView},
                               "Visualization method", methods::kMethodNames, FS_REF(method))),
        param<float>("alpha", kMethodRole.onlyFor({Isa, Ibfvs}),
                     "Noise blend alpha [L eq. 9] (papers: 0.1-0.2)", FS_REF(params.common.alpha), 0, 1),
        param<float>("beta", kMethodRole,
                     "Texture strength beta [L eq. 10]", FS_REF(params.common.beta), 0, 1),
        param<float>("step-px", kMethodRole.onlyFor({Isa, Ibfvs}),
                     "ISA/IBFVS: largest displacement per frame in pixels (dt)", FS_REF(params.common.stepPx), 0, 64),
        param<float>("lic-step-px", kMethodRole.onlyFor({Hybrid}),
                     "Hybrid: arc length per particle integration step in pixels ([W] dt)",
                     FS_REF(params.hybrid.stepPx), 0.05, 64),
        param<float>("speed-percentile", kMethodRole,
                     "Clamp advection speed at this percentile of the surface's speeds (100: no clamp)",
                     FS_REF(params.common.speedPercentile), 1, 100),
        onOff("normalize", kMethodRole,
              "on: unit-length vectors, uniform streaks; off: streak length shows speed",
              FS_REF(params.common.normalize)),
        param<float>("noise-scale", kMethodRole,
                     "Noise cell size s in pixels (papers: 1-10)", FS_REF(params.common.noise.scale), 1, 64),
        param<float>("noise-period", kMethodRole,
                     "Frames per cycle of each noise cell's profile", FS_REF(params.common.noise.period), 2, 10000),
        choice("noise-profile", kMethodRole,
               "Periodic profile w of the noise", methods::kNoiseProfileNames, FS_REF(params.common.noise.profile)),
        param<uint32_t>("seed", kMethodRole,
                        "Noise seed", FS_REF(params.common.noise.seed), 0, 4294967295.0),
        param<int>("grid-res", kMethodRole.onlyFor({Isa}),
                   "ISA advection mesh resolution R (R x R cells)", FS_REF(params.isa.gridRes), 64, 1024),
        choice("isa-warp", kMethodRole.onlyFor({Isa}),
               "ISA texture advection: pixel (mesh interpolated per pixel) or mesh (draw the R x R grid)",
               methods::kIsaWarpNames, FS_REF(params.isa.warp)),
        choice("resample", kMethodRole.onlyFor({Isa, Ibfvs}),
               "ISA/IBFVS: resampling of the advected texture each frame: bicubic (Catmull-Rom, clamped) or "
               "bilinear ([L])", methods::kResampleNames, FS_REF(params.common.resample)),
        choice("noise-injection", kMethodRole.onlyFor({Isa, Ibfvs}),
               "ISA/IBFVS: noise G sampled at the pixel (point, [L]) or averaged along its motion over the frame "
               "(swept)", methods::kNoiseInjectionNames, FS_REF(params.common.noiseInjection)),
    };
}

// Where the GPU work runs, what a camera move does, and each method's own stages.
std::vector<OptionSpec> stageRows() {
    return {
        flag("cull-back-faces", kMethodRole,
             "Skip back-facing triangles (closed, outward-oriented surfaces only)",
             FS_REF(params.common.cullBackFaces)),
        choice("gl-path", kMethodRole,
               "Per-pixel passes as compute or fragment shaders (same images); auto picks per GL renderer",
               methods::kGlPathNames, FS_REF(params.common.glPath)),
        choice("surface-raster", kMethodRole,
               "Who rasterises the surface (ISA's velocity image, the hybrid's seeds, IBFVS's polygon pass): gl, or compute shaders (a "
               "visibility buffer; faster for many small triangles on a software renderer or on GPUs with few "
               "graphics units); auto picks compute " + computeRasterRuleText(),
               methods::kSurfaceRasterNames, FS_REF(params.common.surfaceRaster)),
        choice("parallel", kMethodRole,
               "Several processes on one view (ParaView under MPI): tiles (each runs the image stages on its own "
               "screen tile) or replicate (each runs them on the whole image); the same image",
               methods::kParallelModeNames, FS_REF(params.common.parallel)),
        flag("edge-mask", kMethodRole.onlyFor({Ibfvs}),
             "IBFVS silhouette edge mask over the image [L §IV-E.2]", FS_REF(params.ibfvs.edgeMask)),
        choice("on-camera-move", kMethodRole.onlyFor({Isa, Ibfvs}),
               "When the camera moves: translate (reproject the texture with the surface), freeze, none [L §IV-I]",
               methods::kCameraMoveNames, FS_REF(params.common.onCameraMove)),
        param<int>("filter-length", kMethodRole.onlyFor({Hybrid}),
                   "Hybrid LIC filter length L in samples ([W] 25-70)", FS_REF(params.hybrid.filterLength), 1, 1001),
        choice("kernel", kMethodRole.onlyFor({Hybrid}),
               "Hybrid LIC kernel", methods::kKernelNames, FS_REF(params.hybrid.kernel)),
        onOff("oriented", kMethodRole.onlyFor({Hybrid}),
              "Hybrid: streaks as drops whose bright head points downstream (oriented LIC: sparse noise, "
              "one-sided --kernel), so still images show the flow's sign", FS_REF(params.hybrid.oriented)),
        choice("integrator", kMethodRole.onlyFor({Hybrid}),
               "Hybrid particle integrator (euler as in [W])", methods::kIntegratorNames,
               FS_REF(params.hybrid.integrator)),
        intChoice("noise-size", kMethodRole.onlyFor({Hybrid}),
                  "Hybrid solid noise texels per side", FS_REF(params.hybrid.noiseSize), {64, 128}),
        param<float>("edge-epsilon", kMethodRole.onlyFor({Isa}),
                     "ISA edge detection eps [L eq. 14], depth range per pixel", FS_REF(params.isa.edgeEpsilon), 0, 10),
        onOff("edge-blending", kMethodRole.onlyFor({Isa}),
              "ISA edge blending [L §IV-E.1]", FS_REF(params.isa.edgeBlending)),
        choice("edge-fill", kMethodRole.onlyFor({Isa}),
               "ISA edge blending puts at edge points: noise (eq. 9's history, streaks start at full contrast) or "
               "gray ([L])", methods::kEdgeFillNames, FS_REF(params.isa.edgeFill)),
    };
}

}  // namespace

std::vector<OptionSpec> methodRows() {
    std::vector<OptionSpec> rows = noiseAndAdvectionRows();
    for (OptionSpec& s : stageRows()) rows.push_back(std::move(s));
    return rows;
}

}  // namespace flowsurf::session::rows
