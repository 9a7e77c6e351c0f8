// flowsurf — the option table's rows of what goes in and what comes out: the input and how it
// is read (Data: a change reads the input again; the field and time selection only rebuild),
// and the Output rows (the image, the frames, the files a front end writes, the messages).
#include "session/options/option_rows.h"

namespace flowsurf::session::rows {

std::vector<OptionSpec> inputRows() {
    return {
        text("input", {G::Data, E::Reload, Positional | Config},
             "Surface file (.vtp .vtu .vtk .ply .obj .stl .foam .e .case .pvd), a file series (surf_%04d.vtp, "
             "surf_*.vtp) or builtin:NAME", FS_REF(input), OptionKind::Path),
    };
}

std::vector<OptionSpec> outputRows() {
    return {
        shortNamed("o", text("output", {G::Output, E::Output, CommandLine | Config},
                             "FILE.png (final composite), FILE.mp4 (all frames) or frame_%04d.png", FS_REF(output),
                             OptionKind::Path)),
        {.name = "size",
         .role = {G::Output, E::Rebuild, CommandLine | Config | Renderer},
         .help = "Image size WxH in pixels",
         .kind = OptionKind::Size,
         .min = core::kMinImageSide,
         .max = core::kMaxImageSide,
         .set = [](RenderOptions& o, const std::string& v) { o.size = parseSize(v); },
         .get = [](const RenderOptions& o) {
             return std::to_string(o.size.width) + "x" + std::to_string(o.size.height);
         },
         .arraySeparator = "x"},
        number("frames", {G::Output, E::Rebuild, CommandLine | Config | Renderer},
               "PNG: advection frames before the output frame; MP4 or PNG sequence: frames written",
               &RenderOptions::frames, 0, 100000),
        text("flow-texture", {G::Output, E::Output, CommandLine},
             "Also write the advected texture F_a alone (16-bit gray PNG)", FS_REF(flowTexture), OptionKind::Path),
        number("warmup", {G::Output, E::Rebuild, CommandLine | Config | Renderer | ParaView},
               "Frames advected before the first written frame of an MP4 or PNG sequence and the viewer's start "
               "(-1: enough to look converged, 3/alpha for ISA and IBFVS, 0 for the hybrid)",
               &RenderOptions::warmup, -1, 100000),
        number("fps", {G::Output, E::Output, CommandLine | Config}, "MP4 frame rate", &RenderOptions::fps, 1, 240),
        number("crf", {G::Output, E::Output, CommandLine | Config}, "MP4 H.264 quality, 0 = lossless",
               &RenderOptions::crf, 0, 51),
        shortNamed("q", flag("quiet", {G::Output, E::None, CommandLine | Renderer}, "No progress bar or messages",
                             FS_REF(quiet))),
        shortNamed("v", flag("verbose", {G::Output, E::None, CommandLine | Renderer},
                             "Log the OpenGL renderer and timings", FS_REF(verbose))),
    };
}

namespace {

// The field shown (read, or derived from what is read) and how an OpenFOAM case is read.
std::vector<OptionSpec> readRows() {
    return {
        text("field", {G::Data, E::Reload, CommandLine | Config},
             "Vector array to show (default: the first 3-component point array that is not zero everywhere in the "
             "series), or a derived field: curvature-max, curvature-min, gradient:ARRAY, down:x,y,z, skin-friction (the "
             "wall shear stress from the velocity next to the walls of a volume: OpenFOAM, .vtu/.vtk volumes)",
             FS_REF(field)),
        number("viscosity", {G::Data, E::Reload, CommandLine | Config | Read},
               "Kinematic viscosity in m^2/s for --field skin-friction (0: OpenFOAM's nu from constant/"
               "transportProperties or physicalProperties; none known: direction and a relative magnitude)",
               &RenderOptions::viscosity, 0, 1e30),
        number("curvature-radius", {G::Data, E::Rebuild, CommandLine | Config | Renderer},
               "Derived curvature fields: average the curvature tensor over this radius (object units; 0: one-ring "
               "estimate only)", &RenderOptions::curvatureRadius, 0, 1e30),
        textChoice("reverse-field", {G::Data, E::Rebuild, CommandLine | Config | Panel | Renderer | ParaView},
                   "Show the field reversed (texture, topology, dye): on, off, or auto: reversed when it is "
                   "OpenFOAM's wallShearStress, the stress on the fluid, which points against the near-wall flow",
                   {"auto", "on", "off"}, FS_REF(reverseField)),
        text("patches", {G::Data, E::Reload, CommandLine | Config | Read},
             "OpenFOAM, CGNS: read the boundary patches whose names (CGNS: BC or family names) match this "
             "regular expression (default: the walls: OpenFOAM's wall-type patches, CGNS's BCWall* BCs; all "
             "patches when none is a wall)",
             FS_REF(patches)),
        textChoice("foam-case", {G::Data, E::Reload, CommandLine | Config | Read},
                   "OpenFOAM: read the reconstructed case or the processor* directories of a decomposed one (auto: "
                   "the decomposed one when it has more time directories or the case folder has no mesh)",
                   {"auto", "reconstructed", "decomposed"}, FS_REF(foamCase)),
        flag("foam-zero-time", {G::Data, E::Reload, CommandLine | Config | Read},
             "OpenFOAM: also read the initial conditions in 0/ as a time step (default: 0/ is skipped when solved "
             "time directories exist, as ParaView's Skip Zero Time; a case with only 0/ always reads it)",
             FS_REF(foamZeroTime)),
    };
}

// Which data times the animation shows and how fast.
std::vector<OptionSpec> timeRows() {
    return {
        {.name = "time-step",
         .role = {G::Data, E::Rebuild, CommandLine | Config | Renderer},
         .help = "Render only this time step (index), as steady data",
         .kind = OptionKind::Int,
         .min = 0,
         .max = 1e9,
         .set = [](RenderOptions& o, const std::string& v) {
             if (v.empty()) { o.timeStepGiven = false; o.timeStep = 0; return; }
             double d = parseNumber(v, "--time-step");
             if (d < 0 || d > 1e9 || d != std::floor(d))
                 throw ConfigError("--time-step: '" + v + "' is not a step index");
             o.timeStep = size_t(d);
             o.timeStepGiven = true;
         },
         .get = [](const RenderOptions& o) { return o.timeStepGiven ? std::to_string(o.timeStep) : std::string(); }},
        {.name = "time",
         .role = {G::Data, E::Rebuild, CommandLine | Config | Renderer},
         .help = "Data time range START:END of the animation (default: the whole series)",
         .set = [](RenderOptions& o, const std::string& v) {
             if (v.empty()) { o.timeRange.reset(); return; }
             auto colon = v.find(':');
             if (colon == std::string::npos || v.find(':', colon + 1) != std::string::npos)
                 throw ConfigError("--time: '" + v + "' is not START:END");
             o.timeRange = std::make_pair(parseNumber(v.substr(0, colon), "--time"),
                                          parseNumber(v.substr(colon + 1), "--time"));
         },
         .get = [](const RenderOptions& o) {
             return o.timeRange ? formatDouble(o.timeRange->first) + ":" + formatDouble(o.timeRange->second)
                                : std::string();
         },
         .arraySeparator = ":"},
        number("time-per-frame", {G::Data, E::Rebuild, CommandLine | Config | Renderer},
               "Data time per animation frame (0: see --frames-per-step)", &RenderOptions::timePerFrame, 0, 1e30),
        number("frames-per-step", {G::Data, E::Rebuild, CommandLine | Config | Renderer},
               "Animation frames per data time step (0: the range over --frames)", &RenderOptions::framesPerStep, 0,
               100000),
        {.name = "trace-dt",
         .role = OptionRole{G::Data, E::Rebuild, CommandLine | Config | Renderer}.onlyFor({Hybrid}),
         .help = "Hybrid on a time series: data time per particle step, so the LIC follows pathlines (default: the "
                 "data time per frame; 0: streamlines of each frame's field)",
         .kind = OptionKind::Float,
         .min = 0,
         .max = 1e30,
         .set = [](RenderOptions& o, const std::string& v) {
             if (v.empty()) { o.traceDt.reset(); return; }
             double d = parseNumber(v, "--trace-dt");
             if (d < 0) throw ConfigError("--trace-dt: " + v + " must not be negative");
             o.traceDt = d;
         },
         .get = [](const RenderOptions& o) { return o.traceDt ? formatDouble(*o.traceDt) : std::string(); }},
    };
}

}  // namespace

std::vector<OptionSpec> dataRows() {
    std::vector<OptionSpec> rows = readRows();
    for (OptionSpec& s : timeRows()) rows.push_back(std::move(s));
    return rows;
}

}  // namespace flowsurf::session::rows

namespace flowsurf::session {

bool fieldShownReversed(const RenderOptions& o, const std::string& field) {
    if (o.reverseField == "on") return true;
    if (o.reverseField == "off") return false;
    return field == "wallShearStress";
}

}  // namespace flowsurf::session
