// flowsurf — parameters of the methods: plain structs, in-class defaults, one line each
// with unit and the papers' range. No globals: methods run side by side.
#pragma once

#include "core/noise.h"

#include <glm/glm.hpp>

#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flowsurf::methods {

enum class Colormap { None, Viridis, CoolWarm, Gray, Turbo, Jet, Plasma };

// How the flow texture meets the surface in the displayed image. Blend: eq. 10 of [L]
// with the colour map and lighting; the others are the colour schemes of [W Fig. 6]:
// gray texture alone; gray x lit gray surface; texture on a blue-yellow hue ramp x lit
// surface; gray x cool/warm (Gooch) shading.
enum class OverlayScheme { Blend, Gray, GrayLit, HueLit, CoolWarm };

// What happens to the image-space texture when the camera moves [L §IV-I, §5 of
// doc/algorithms.md]. None: the pattern slides over the surface. Translate: the previous
// texture is reprojected with the surface's image motion (per pixel: good for pan,
// rotate and zoom). Freeze: no advection while the camera moves; the last texture is
// mapped onto the surface from the view where it was made; resumes when it stops.
enum class CameraMoveRemedy { None, Translate, Freeze };

// How ISA and IBFVS resample the previous F_a at the backward-integrated coordinates
// each frame (shaders/image_space/resample.glsl). Bilinear: the texture filter, as in [L]; its
// numerical diffusion blurs across the flow as much as along it. Bicubic: Catmull-Rom,
// clamped to the four nearest texels.
enum class Resample { Bilinear, Bicubic };

// How ISA and IBFVS inject the noise G of eq. 9 (shaders/image_space/noise_injection.glsl).
// Point: G at the pixel, as in [L]; noise finer than the step leaves dotted streaks.
// Swept: G averaged along the pixel's image motion over the frame, x - t d' for t in
// [0,1): a box filter along the flow over one step, so the noise is band-limited to the
// step along the flow and keeps its full resolution across it.
enum class NoiseInjectionMode { Point, Swept };

// Which GL stage runs the per-pixel passes (hybrid particle tracing, ISA/IBFVS advection
// with noise injection, the overlay). Fragment: full-screen triangles into framebuffers.
// Compute: compute-shader dispatches writing images; the same images (tests compare both).
// Auto: chosen per GL renderer (methods::resolveGlPath).
enum class GlPath { Auto, Compute, Fragment };

// Who rasterises the surface into the per-pixel buffers (ISA's velocity image, the hybrid's
// seed textures, IBFVS's polygon pass). Gl: the GL rasteriser. Compute: a visibility buffer
// filled by compute shaders, one invocation per triangle (raster/visibility_buffer.h);
// the same buffers up to float rounding. Auto: compute on a software renderer or a GPU with
// few graphics units when the triangles are many for the image (methods::useComputeRaster),
// else GL.
enum class SurfaceRaster { Auto, Gl, Compute };

// How processes that render one view together (sort-last, each with a piece of the
// surface: the ParaView plugin under MPI) share the image stages. Tiles: each process runs
// them on its own screen tile plus a guard band, with the buffers merged there only
// (parallel/screen_tiles.h). Replicate: every process merges the whole image and
// runs every stage on all of it (parallel/process_group.h; the reference).
enum class ParallelMode { Tiles, Replicate };

// Where a colour or mask range comes from when none is given as MIN:MAX [docs/cfd.md, colour ranges].
// Robust: core::robustRange (Tukey's fences on area-weighted quartiles) over all time
// steps; Data: the minimum and maximum over all time steps.
enum class RangeMode { Robust, Data };

// How colour values map onto the colour map: linearly, or by their log10 (positive ranges).
enum class ColorScale { Linear, Log };

// Contrast enhancement [doc/contrast.md], as ParaView's Surface LIC offers it: which images
// are stretched between robust percentiles of the surface's pixels each frame
// (present/contrast_stretch.h). Texture: the flow texture's intensity (F_a or I)
// before the overlay; Color: the lightness of the surface's colour after it; Both.
enum class EnhanceContrast { Off, Texture, Color, Both };

// Eq. 9 and 10, shared by every method.
struct CommonParams {
    float alpha = 0.08f;         // noise blend alpha, [L] 0.1..0.2 (streak length ~ stepPx / alpha)
    float beta = 0.55f;          // texture strength beta in eq. 10, 0..1
    // ISA/IBFVS: largest displacement per frame, pixels ([L] dt). 4 with swept noise
    // (doc/algorithms.md §2, swept noise); the paper's point-sampled noise needs stepPx <= noise scale.
    float stepPx = 4.0f;
    // Advection speed: vectors faster than this percentile of the surface's speeds are
    // clamped to it (CFD fields span decades; the max would freeze most of the
    // surface). 100 = no clamping. Streak length shows speed below it.
    float speedPercentile = 95.0f;
    // Unit-length vectors: uniform streak length [W Fig. 5]. On by default, as in
    // ParaView's Surface LIC: CFD wall fields span decades of magnitude.
    bool normalize = true;
    core::NoiseParams noise;     // scale s (px), period, profile, seed
    float contrast = 2.5f;       // display gain of F_a about the noise mean (overlay only; 1 when the texture is enhanced)
    // Contrast enhancement [doc/contrast.md]: what is stretched, the percent of surface pixels
    // clamped at each end of a stretch (0..25; ParaView's factors 0 / 0.99 ~ 0 and 1), and
    // the frames over which the percentiles are smoothed (exponential, time constant
    // 1..1000 frames; 1: each frame's own), so that an animation does not pulse.
    EnhanceContrast enhanceContrast = EnhanceContrast::Off;
    float enhancePercentile = 1.0f;
    float enhanceSmoothing = 8.0f;
    OverlayScheme overlay = OverlayScheme::Blend;
    Colormap colormap = Colormap::Viridis;  // colour map of speed in F_s
    bool lighting = true;        // diffuse head light in F_s
    bool velocityMask = false;   // texture contrast follows speed [L ref 14]
    // Colour by: "" = the shown field's speed; else ARRAY or ARRAY:x|y|z|mag (core::ScalarSpec).
    std::string colorBy;
    // Values at the ends of the colour map. lo > hi (unset): the session fills in the
    // range colorRangeMode makes over all time steps (speed: 0 .. its 98th percentile when
    // robust, its maximum with data); colorRangeAuto: each frame's own data range.
    glm::vec2 colorRange{1.0f, 0.0f};
    bool colorRangeAuto = false;
    RangeMode colorRangeMode = RangeMode::Robust;
    ColorScale colorScale = ColorScale::Linear;
    // Texture contrast follows this scalar (as velocityMask does speed) over maskRange
    // (lo > hi: from maskRangeMode over all time steps, or each frame's with maskRangeAuto).
    // Empty: off, or speed with velocityMask.
    std::string maskBy;
    glm::vec2 maskRange{1.0f, 0.0f};
    bool maskRangeAuto = false;
    RangeMode maskRangeMode = RangeMode::Robust;
    // A colour map read from a ParaView JSON file (RGBPoints), 256 sRGB entries; replaces
    // `colormap` when not empty.
    std::string colormapFile;
    std::vector<glm::vec3> colormapTable;
    bool legend = false;         // scalar bar with title and ticks, drawn into the composite
    std::string title;           // legend title (default: the colour array's name)
    glm::vec3 background{0.11f, 0.11f, 0.13f};  // linear RGB 0..1
    CameraMoveRemedy onCameraMove = CameraMoveRemedy::Translate;
    Resample resample = Resample::Bicubic;  // F_a resampling in ISA and IBFVS ([L]: bilinear)
    NoiseInjectionMode noiseInjection = NoiseInjectionMode::Swept;  // ISA and IBFVS ([L]: point)
    // Skip back-facing triangles in the surface passes: cheaper for closed, consistently
    // oriented surfaces (counter-clockwise seen from outside); wrong for open CFD walls,
    // which are seen from both sides, so off by default. Off-screen triangles are always
    // clipped by the rasteriser before they cost fragment work.
    bool cullBackFaces = false;
    GlPath glPath = GlPath::Auto;  // per-pixel passes as compute or fragment shaders
    SurfaceRaster surfaceRaster = SurfaceRaster::Auto;  // who rasterises the surface passes
    ParallelMode parallel = ParallelMode::Tiles;  // image stages over processes (one process: no effect)
};

// How ISA's texture advection applies the advection mesh (see isa/texture_advection.h).
enum class IsaWarp { Pixel, Mesh };

// What ISA's edge blending puts at edge advection points [L §IV-E.1]. Gray: the noise
// mean, as in [L]; streaks then need ~1/alpha frames to regain contrast. Noise: the
// history eq. 9 would have left there (noise integrated along the pathline extended
// upstream), so streaks start at the interior's contrast.
enum class EdgeFill { Gray, Noise };

// ISA only, [L §IV-C.1..IV-F.1].
struct IsaParams {
    IsaWarp warp = IsaWarp::Pixel;  // Mesh: draw the R x R grid as in the paper
    int gridRes = 256;           // R: advection mesh cells per side, 64..1024
    float edgeEpsilon = 0.01f;   // eps of eq. 14: depth range fraction per pixel
    bool edgeBlending = true;    // replace the advected texture at edge advection points
    EdgeFill edgeFill = EdgeFill::Noise;  // with what ([L]: gray); doc/algorithms.md §3
};

// IBFVS only, [L §IV-C.2..IV-F.2].
struct IbfvsParams {
    float flowBackground = core::kNoiseMean;  // F_a outside the surface: the noise mean, inflow invisible
    bool edgeMask = false;        // silhouette edge mask over the display [L §IV-E.2]
    float edgeMaskWidthPx = 2.0f; // line width of the mask
    float edgeMaskOpacity = 0.85f;
};

enum class LicKernel { Box, Exponential, Gaussian, Hann };
enum class Integrator { Euler, Rk2, Rk4 };

// Hybrid physical/device-space LIC only, [W §3-6].
struct HybridParams {
    int filterLength = 31;            // L: samples along the streamline, [W] 25..70
    float stepPx = 2.0f;              // arc length per integration step, pixels ([W] dt)
    LicKernel kernel = LicKernel::Gaussian;
    Integrator integrator = Integrator::Euler;  // as in [W]; RK2/RK4 on request
    int noiseSize = 64;               // solid noise texels per side: 64 or 128
    float depthTolerance = 0.03f;     // particle vs visible layer, fraction of depth range
    // Oriented LIC [Wegenkittl, Groller, Purgathofer 1997]: sparse solid noise and a one-sided
    // kernel, so each streak is a drop whose bright head points downstream (still images show
    // the sign). Off: the symmetric texture of [W]. Needs a kernel with a falloff (not box).
    bool oriented = false;
};

// Whether `e` stretches the flow texture / the colour's lightness.
constexpr bool enhancesTexture(EnhanceContrast e) { return e == EnhanceContrast::Texture || e == EnhanceContrast::Both; }
constexpr bool enhancesColor(EnhanceContrast e) { return e == EnhanceContrast::Color || e == EnhanceContrast::Both; }

struct MethodParams {
    CommonParams common;
    IsaParams isa;
    IbfvsParams ibfvs;
    HybridParams hybrid;
};

// The names of the enum values: one table per enum, used by the command line, config
// files, the viewer and every other front end (src/session/options.cpp).
template <typename E, size_t N>
using EnumNames = std::array<std::pair<E, std::string_view>, N>;

inline constexpr EnumNames<Colormap, 7> kColormapNames{{{Colormap::Viridis, "viridis"},
                                                        {Colormap::CoolWarm, "coolwarm"},
                                                        {Colormap::Gray, "gray"},
                                                        {Colormap::Turbo, "turbo"},
                                                        {Colormap::Jet, "jet"},
                                                        {Colormap::Plasma, "plasma"},
                                                        {Colormap::None, "none"}}};
inline constexpr EnumNames<ColorScale, 2> kColorScaleNames{{{ColorScale::Linear, "linear"}, {ColorScale::Log, "log"}}};
inline constexpr EnumNames<EnhanceContrast, 4> kEnhanceContrastNames{{{EnhanceContrast::Off, "off"},
                                                                        {EnhanceContrast::Texture, "texture"},
                                                                        {EnhanceContrast::Color, "color"},
                                                                        {EnhanceContrast::Both, "both"}}};
inline constexpr EnumNames<OverlayScheme, 5> kOverlayNames{{{OverlayScheme::Blend, "blend"},
                                                            {OverlayScheme::Gray, "gray"},
                                                            {OverlayScheme::GrayLit, "gray-lit"},
                                                            {OverlayScheme::HueLit, "hue-lit"},
                                                            {OverlayScheme::CoolWarm, "coolwarm"}}};
inline constexpr EnumNames<CameraMoveRemedy, 3> kCameraMoveNames{{{CameraMoveRemedy::Translate, "translate"},
                                                                  {CameraMoveRemedy::Freeze, "freeze"},
                                                                  {CameraMoveRemedy::None, "none"}}};
inline constexpr EnumNames<IsaWarp, 2> kIsaWarpNames{{{IsaWarp::Pixel, "pixel"}, {IsaWarp::Mesh, "mesh"}}};
inline constexpr EnumNames<EdgeFill, 2> kEdgeFillNames{{{EdgeFill::Noise, "noise"}, {EdgeFill::Gray, "gray"}}};
inline constexpr EnumNames<LicKernel, 4> kKernelNames{{{LicKernel::Box, "box"},
                                                       {LicKernel::Exponential, "exponential"},
                                                       {LicKernel::Gaussian, "gaussian"},
                                                       {LicKernel::Hann, "hann"}}};
inline constexpr EnumNames<Integrator, 3> kIntegratorNames{{{Integrator::Euler, "euler"},
                                                            {Integrator::Rk2, "rk2"},
                                                            {Integrator::Rk4, "rk4"}}};
inline constexpr EnumNames<core::NoiseProfile, 2> kNoiseProfileNames{{{core::NoiseProfile::Square, "square"},
                                                                      {core::NoiseProfile::Sawtooth, "sawtooth"}}};
inline constexpr EnumNames<Resample, 2> kResampleNames{{{Resample::Bicubic, "bicubic"}, {Resample::Bilinear, "bilinear"}}};
inline constexpr EnumNames<NoiseInjectionMode, 2> kNoiseInjectionNames{{{NoiseInjectionMode::Swept, "swept"},
                                                                         {NoiseInjectionMode::Point, "point"}}};
inline constexpr EnumNames<GlPath, 3> kGlPathNames{{{GlPath::Auto, "auto"},
                                                     {GlPath::Compute, "compute"},
                                                     {GlPath::Fragment, "fragment"}}};
inline constexpr EnumNames<SurfaceRaster, 3> kSurfaceRasterNames{{{SurfaceRaster::Auto, "auto"},
                                                                   {SurfaceRaster::Gl, "gl"},
                                                                   {SurfaceRaster::Compute, "compute"}}};
inline constexpr EnumNames<ParallelMode, 2> kParallelModeNames{{{ParallelMode::Tiles, "tiles"},
                                                                 {ParallelMode::Replicate, "replicate"}}};
// The methods: ISA and IBFVS [L], the hybrid physical/device-space LIC [W]; in the order
// the viewer cycles through them.
enum class Method { Isa, Ibfvs, Hybrid };
inline constexpr EnumNames<Method, 3> kMethodNames{{{Method::Isa, "isa"},
                                                    {Method::Ibfvs, "ibfvs"},
                                                    {Method::Hybrid, "hybrid"}}};

// The name of `value` in its table (empty if it has none).
template <typename E, size_t N>
constexpr std::string_view nameOf(const EnumNames<E, N>& names, E value) {
    for (const auto& [v, text] : names)
        if (v == value) return text;
    return {};
}

// The value named `text`, or false.
template <typename E, size_t N>
constexpr bool valueOf(const EnumNames<E, N>& names, std::string_view text, E* value) {
    for (const auto& [v, name] : names)
        if (name == text) {
            *value = v;
            return true;
        }
    return false;
}

// Every name of the table, in table order (default lists, command-line checks).
template <typename E, size_t N>
std::vector<std::string> names(const EnumNames<E, N>& table) {
    std::vector<std::string> out;
    for (const auto& [v, text] : table) out.emplace_back(text);
    return out;
}

// "isa, ibfvs, hybrid": the names in table order, for help texts and error messages.
template <typename E, size_t N>
std::string nameList(const EnumNames<E, N>& names) {
    std::string list;
    for (const auto& [v, text] : names) list += (list.empty() ? "" : ", ") + std::string(text);
    return list;
}

}  // namespace flowsurf::methods
