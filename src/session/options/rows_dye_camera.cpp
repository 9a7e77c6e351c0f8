// flowsurf — the option table's Dye and Camera rows. Dye [doc/algorithms.md §10]: changes apply live
// (session::Playback), effect None; the viewer's panel lists the sources with a widget of its
// own. Camera: a change gives new cameras from the next frame while the textures and the
// clock go on; the panel edits the view itself (eye, target, up, fov, ortho).
#include "session/options/dye_sources.h"
#include "session/options/option_rows.h"

namespace flowsurf::session::rows {

std::vector<OptionSpec> dyeRows() {
    return {
        {.name = "dye",
         .role = {G::Dye, E::None, CommandLine | Config | PanelOwn | Renderer | ParaView},
         .help = "Dye source X,Y,Z[:RADIUS[:COLOR]] (repeatable, or ';'-separated): ink released at the surface "
                 "point nearest X,Y,Z, RADIUS in object units (0: " + formatFloat(methods::kDyeRadiusPx) +
                 " pixels at the first frame's view), COLOR a name (red, green, blue, yellow, cyan, magenta, "
                 "orange...), #rrggbb or r,g,b",
         .set = [](RenderOptions& o, const std::string& v) { o.dye = parseDyeSources(v, "--dye"); },
         .get = [](const RenderOptions& o) { return dyeSourcesText(o.dye); },
         .repeatable = true},
        number("dye-release", {G::Dye, E::None, CommandLine | Config | Panel | Renderer | ParaView},
               "Frames a dye source emits from its start (0: continuously, a streakline; N: a blob that then "
               "travels)", &RenderOptions::dyeRelease, 0, 100000000),
        number("dye-decay", {G::Dye, E::None, CommandLine | Config | Panel | Renderer | ParaView},
               "Dye fades at this rate per data time unit (0: never)", &RenderOptions::dyeDecay, 0, 1e30),
        {.name = "dye-file",
         .role = {G::Dye, E::None, CommandLine | Config | Panel | Renderer | ParaView},
         .help = "Dye sources from a JSON file: [{\"point\": [x,y,z], \"radius\": r, \"color\": \"red\", \"start\": "
                 "frame, \"stop\": frame}, ...] (see README)",
         .kind = OptionKind::Path,
         .set = [](RenderOptions& o, const std::string& v) {
             o.dyeFileSources = v.empty() ? std::vector<methods::DyeSource>{} : readDyeFile(v);
             o.dyeFile = v;
         },
         .get = [](const RenderOptions& o) { return o.dyeFile; }},
    };
}

std::vector<OptionSpec> cameraRows() {
    return {
        vec3("eye", {G::Camera, E::Camera, CommandLine | Config | Panel | Renderer},
             "Eye position x,y,z (default: fit the bounds)", &RenderOptions::eye),
        vec3("target", {G::Camera, E::Camera, CommandLine | Config | Panel | Renderer},
             "Look-at point x,y,z (default: centre of the bounds)", &RenderOptions::target),
        vec3("up", {G::Camera, E::Camera, CommandLine | Config | Panel | Renderer}, "Up vector x,y,z (default 0,1,0)",
             &RenderOptions::up),
        number("fov", {G::Camera, E::Camera, CommandLine | Config | Panel | Renderer},
               "Vertical field of view in degrees", &RenderOptions::fov, 1, 170),
        number("ortho", {G::Camera, E::Camera, CommandLine | Config | Panel | Renderer},
               "Orthographic view with this view height (object units; 0: perspective)", &RenderOptions::ortho, 0,
               1e30),
        number("orbit", {G::Camera, E::Camera, CommandLine | Config | Renderer},
               "Camera turns this many degrees per frame about the up axis (dynamic case)", &RenderOptions::orbit,
               -180, 180),
        choice("view", {G::Camera, E::Camera, CommandLine | Config | Renderer},
               "View preset as ParaView's camera buttons: +x, -x, +y, -y, +z, -z (look along that direction) "
               "or iso (default: front, a little above and to the right)",
               kViewPresetNames, FS_REF(view)),
        {.name = "up-axis",
         .role = {G::Camera, E::Camera, CommandLine | Config | Renderer},
         .help = "The data's up axis (many CFD cases are z-up): orients --view and the default view",
         .kind = OptionKind::Choice,
         .choices = {"x", "y", "z"},
         .set = [](RenderOptions& o, const std::string& v) {
             if (v != "x" && v != "y" && v != "z") throw ConfigError("--up-axis: '" + v + "' is not one of x, y, z");
             o.upAxis = v[0] - 'x';
         },
         .get = [](const RenderOptions& o) { return std::string(1, char('x' + o.upAxis)); }},
        text("camera-path", {G::Camera, E::Camera, CommandLine | Config | Renderer},
             "Keyframed camera path (JSON); see README", FS_REF(cameraPath), OptionKind::Path),
    };
}

}  // namespace flowsurf::session::rows
