// flowsurf — the option table's Overlay rows: how the flow texture is shown over the surface
// [L eq. 10] (colour, masks, contrast, background). Each row declares its role: a change
// rebuilds the renderers; the viewer's panel shows them as widgets; ParaView takes those it
// does not do itself (its own colour map, lighting and background).
#include "session/options/colormap_file.h"
#include "session/options/option_rows.h"

namespace flowsurf::session::rows {

namespace {

// Colour by a scalar through a colour map, its range and scale, and the legend.
std::vector<OptionSpec> colourRows() {
    return {
        choice("overlay", kOverlayRole,
               "blend (eq. 10: texture + colour map x lighting); or [W Fig. 6]: gray, gray-lit, hue-lit, coolwarm",
               methods::kOverlayNames, FS_REF(params.common.overlay)),
        choice("colormap", kOverlayRoleNotParaView, "Colour map",
               methods::kColormapNames, FS_REF(params.common.colormap)),
        {.name = "colormap-file",
         .role = kOverlayRole,
         .help = "Colour map from a ParaView JSON preset file (RGBPoints); replaces --colormap",
         .kind = OptionKind::Path,
         .set = [](RenderOptions& o, const std::string& v) {
             o.params.common.colormapFile = v;
             o.params.common.colormapTable = v.empty() ? std::vector<glm::vec3>{} : readParaViewColormap(v);
         },
         .get = [](const RenderOptions& o) { return o.params.common.colormapFile; }},
        scalarSpec("color-by", kOverlayRole,
                   "Colour by ARRAY (a point or cell scalar, or a vector's magnitude) or ARRAY:x|y|z|mag (default: "
                   "the shown field's speed)", FS_REF(params.common.colorBy)),
        rangeOption("color-range", kOverlayRole,
                    "Values at the ends of the colour map: robust (the bulk of the data over all time steps, outliers "
                    "clamped: Tukey's fences on area-weighted quartiles), data (min:max over all time steps), auto "
                    "(each frame's min:max) or MIN:MAX", FS_REF(params.common.colorRange),
                    FS_REF(params.common.colorRangeAuto), FS_REF(params.common.colorRangeMode),
                    RangeRescale::DataAndView),
        choice("color-scale", kOverlayRole,
               "Colour map scale: linear, or log (log10 of the values; the range must be positive)",
               methods::kColorScaleNames, FS_REF(params.common.colorScale)),
        flag("legend", kOverlayRole,
             "Draw a colour legend (scalar bar with title and ticks) into the image", FS_REF(params.common.legend)),
        text("title", kOverlayRole,
             "Legend title (default: the colour array's name)", FS_REF(params.common.title)),
    };
}

// The texture's contrast (masks, gain, enhancement), the lighting and the background.
std::vector<OptionSpec> contrastRows() {
    return {
        scalarSpec("mask-by", kOverlayRole,
                   "Texture contrast follows this scalar (ARRAY or ARRAY:x|y|z|mag), as --velocity-mask does speed "
                   "([L] Fig. 13)", FS_REF(params.common.maskBy)),
        rangeOption("mask-range", kOverlayRole,
                    "Values of --mask-by at zero and full contrast: robust, data, auto or MIN:MAX, as --color-range",
                    FS_REF(params.common.maskRange), FS_REF(params.common.maskRangeAuto),
                    FS_REF(params.common.maskRangeMode), RangeRescale::Data),
        onOff("lighting", kOverlayRoleNotParaView, "Diffuse lighting",
              FS_REF(params.common.lighting)),
        flag("velocity-mask", kOverlayRole,
             "Texture contrast follows speed [L ref 14]", FS_REF(params.common.velocityMask)),
        param<float>("contrast", kOverlayRole,
                     "Display gain of the flow texture about its mean (not applied to a texture --enhance-contrast "
                     "stretches)", FS_REF(params.common.contrast), 0, 20),
        choice("enhance-contrast", kOverlayRole,
               "Contrast enhancement as ParaView's Surface LIC: stretch the flow texture's intensity (texture), the "
               "surface colour's lightness (color) or both between robust percentiles of the surface's pixels, "
               "smoothed over frames (see doc/contrast.md)", methods::kEnhanceContrastNames,
               FS_REF(params.common.enhanceContrast)),
        param<float>("enhance-percentile", kOverlayRole,
                     "Contrast enhancement: percent of the surface's pixels clamped at each end of the stretch",
                     FS_REF(params.common.enhancePercentile), 0, 25),
        param<float>("enhance-smoothing", kOverlayRole,
                     "Contrast enhancement: frames over which the stretch's percentiles are smoothed (time constant; "
                     "1: each frame's own)", FS_REF(params.common.enhanceSmoothing), 1, 1000),
        {.name = "background",
         .role = kOverlayRoleNotParaView,
         .help = "Background colour: #RRGGBB, r,g,b in 0..1, black, white, gray",
         .kind = OptionKind::Color,
         .min = 0,
         .max = 1,
         .set = [](RenderOptions& o, const std::string& v) { o.params.common.background = parseColor(v); },
         .get = [](const RenderOptions& o) { return vec3Text(o.params.common.background); }},
    };
}

}  // namespace

// The flow topology: what is analysed and how it is drawn (doc/topology.md).
std::vector<OptionSpec> topologyRows() {
    return {
        onOff("topology", kOverlayRole,
              "Draw the flow topology over the texture: critical points as glyphs by type, separation (red) and "
              "attachment (blue) lines, hidden where the surface covers them", FS_REF(topology)),
        textChoice("topology-parts", kOverlayRole,
                   "Which parts of the topology to draw: points,lines, points or lines",
                   {"points,lines", "points", "lines"}, FS_REF(topologyParts)),
        param<float>("topology-scale", kOverlayRole,
                     "Topology: smooth the field and fit its Jacobian over this radius (object units; 0: 3 median "
                     "edge lengths)", FS_REF(topologyParams.scale), 0, 1e30),
        param<float>("topology-cancel-speed", kOverlayRole,
                     "Topology: zeros joined through a region slower than this fraction of the 99th-percentile speed "
                     "merge into their net index (noise pairs cancel; 0: none merge)",
                     FS_REF(topologyParams.cancelSpeed), 0, 1),
        param<float>("topology-line-strength", kOverlayRole,
                     "Topology: drop lines whose mean strength (|rate across - rate along| x diagonal / 99th-"
                     "percentile speed) is below this", FS_REF(topologyParams.lineStrength), 0, 1e6),
        param<float>("topology-line-length", kOverlayRole,
                     "Topology: drop lines shorter than this fraction of the bounding-box diagonal",
                     FS_REF(topologyParams.lineLength), 0, 1),
        param<float>("topology-glyph-size", kOverlayRole, "Topology: glyph size in pixels",
                     FS_REF(topologyGlyphSize), 4, 64),
        param<float>("topology-line-width", kOverlayRole, "Topology: line width in pixels",
                     FS_REF(topologyLineWidth), 1, 16),
    };
}

std::vector<OptionSpec> overlayRows() {
    std::vector<OptionSpec> rows = colourRows();
    for (OptionSpec& s : contrastRows()) rows.push_back(std::move(s));
    for (OptionSpec& s : topologyRows()) rows.push_back(std::move(s));
    return rows;
}

}  // namespace flowsurf::session::rows
